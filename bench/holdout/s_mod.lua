-- s_mod.st in Lua 5.4, the same computation; prints the checksum (777007).
local tot = 0
for nn = 1, 1000000 do
  local xx = nn % 1000
  local yy = (xx * 3) // 7
  if yy > 300 then tot = tot + yy - 300
  elseif yy > 100 then tot = tot + 1
  else tot = tot - yy end
  if tot > 1000000 then tot = tot - 999999 end
  if tot < -1000000 then tot = tot + 999999 end
end
result = tot
print(result)
