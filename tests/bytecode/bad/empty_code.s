; an image without code

; expect verify: EmptyCode
