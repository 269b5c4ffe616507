-- p_div.pdl in Lua 5.4, the same computation (q rounded to nearest, as PDL's `/` into an
-- integer rounds); prints the checksum (857101).
local s = 0
for i = 1, 1000000 do
  local q = math.floor(i / 7 + 0.5)
  local r = i % 7
  s = s + q
  s = s - r
  if s > 1000000 then s = s - 999983 end
  local f = i * 0.5
  local g = f / 3.0
end
result = s
print(result)
