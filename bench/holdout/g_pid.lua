-- g_pid.ehl in Lua 5.4, the same computation; prints the checksum.
gp, gi, gd = 0.6, 0.05, 0.2
integ, prev, y, u = 0.0, 0.0, 0.0, 0.0
local acc = 0.0
for k = 1, 1000000 do
  local spt
  if (k % 2000) < 1000 then spt = 100.0 else spt = -50.0 end
  local e = spt - y
  integ = integ + e * 0.001
  if integ > 50.0 then integ = 50.0 end
  if integ < -50.0 then integ = -50.0 end
  local d = e - prev
  prev = e
  u = gp * e + gi * integ + gd * d
  y = y + (u - y) * 0.05
  if e < 0.0 then acc = acc - e else acc = acc + e end
end
result = acc
print(string.format("%.17g", result))
