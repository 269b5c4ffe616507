-- g_call4.ehl in Lua 5.4, the same computation; prints the checksum.
local function mix(a, b, c, d)
  local t = (a + b * c + d) % 1000003
  if t > 1000000 then
    t = t - 999983
  end
  return t
end
local s = 0
for i = 1, 1500000 do
  s = mix(s, i, i % 13, 7)
end
result = s
print(result)
