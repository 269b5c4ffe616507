-- p_proc.pdl in Lua 5.4, the same computation; prints the checksum.
local function mix(a, b, c)
  local t = b * c
  t = t + a
  t = t + 7
  t = t % 1000003
  return t
end
local s = 0
for i = 1, 3000000 do
  local c = i % 13
  s = mix(s, i, c)
end
result = s
print(result)
