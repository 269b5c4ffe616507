-- p_float.pdl in Lua 5.4, the same computation; prints the checksum.
local x, y1, y2, y, a1, a2, b0, t, acc
a1 = 1.6; a2 = -0.64; b0 = 0.04
y1 = 0.0; y2 = 0.0; acc = 0.0
local ph = 0
local i = 0
while i < 2000000 do
  ph = ph + 1
  if ph >= 50 then ph = 0 end
  x = ph
  x = x - 25
  y = b0 * x
  t = a1 * y1
  y = y + t
  t = a2 * y2
  y = y + t
  y2 = y1
  y1 = y
  if y > 0.0 then acc = acc + y else acc = acc - y end
  i = i + 1
end
result = acc
print(string.format("%.17g", result))
