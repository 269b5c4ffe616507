-- g_pid in float32 arithmetic, as the drive computes it: the checksum uprog must print (not timed).
local function f(x) return (string.unpack("f", string.pack("f", x))) end
local gp, gi, gd = f(0.6), f(0.05), f(0.2)
local integ, prev, y, u = 0.0, 0.0, 0.0, 0.0
local acc = 0.0
local c001, c05 = f(0.001), f(0.05)
for k = 1, 1000000 do
  local spt
  if (k % 2000) < 1000 then spt = 100.0 else spt = -50.0 end
  local e = f(spt - y)
  integ = f(integ + f(e * c001))
  if integ > 50.0 then integ = 50.0 end
  if integ < -50.0 then integ = -50.0 end
  local d = f(e - prev)
  prev = e
  u = f(f(f(gp * e) + f(gi * integ)) + f(gd * d))
  y = f(y + f(f(u - y) * c05))
  if e < 0.0 then acc = f(acc - e) else acc = f(acc + e) end
end
print(string.format("%.17g", acc))
