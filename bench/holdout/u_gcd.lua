-- u_gcd.pup in Lua 5.4, the same computation; prints the checksum.
local sm, cop = 0, 0
for a = 1, 3000 do
  for b = 1, 300 do
    local x, y = a, b
    while y ~= 0 do
      local t = x % y
      x = y
      y = t
    end
    sm = sm + x
    if x == 1 then cop = cop + 1 end
  end
end
result = sm + cop
print(result)
