-- bench/peers/arrays.lua with 960 elements (what PUP's AGenData holds, arrays960.pup): 3000
-- rounds of fill a[i]=(i*7919+round)%960, then sum, min and max; the checksum below 1000000.
local a = {}
for i = 0, 959 do a[i] = 0 end
local total = 0
for r = 1, 3000 do
  for i = 0, 959 do
    a[i] = (i * 7919 + r) % 960
  end
  local s, mn, mx = 0, a[0], a[0]
  for i = 0, 959 do
    local v = a[i]
    s = s + v
    if v < mn then mn = v end
    if v > mx then mx = v end
  end
  total = (total + s + mn + mx) % 1000000
end
print(total)
