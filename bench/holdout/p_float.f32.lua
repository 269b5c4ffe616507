-- p_float in float32 arithmetic, as the drive computes it: the checksum uprog must print (not timed).
local function f(v) return (string.unpack("f", string.pack("f", v))) end
local a1, a2, b0 = f(1.6), f(-0.64), f(0.04)
local y1, y2, acc, ph, i = 0.0, 0.0, 0.0, 0, 0
while i < 2000000 do
  ph = ph + 1
  if ph >= 50 then ph = 0 end
  local x = f(ph - 25)
  local y = f(b0 * x)
  y = f(y + f(a1 * y1))
  y = f(y + f(a2 * y2))
  y2 = y1; y1 = y
  if y > 0.0 then acc = f(acc + y) else acc = f(acc - y) end
  i = i + 1
end
print(string.format("%.17g", acc))
