-- s_branch.st in Lua 5.4, the same computation; prints the checksum.
local a, b, c, d, k = 0, 0, 0, 0, 0
for i = 1, 10000 do
  for j = 1, 400 do
    k = k + 1
    if k == 10 then k = 0 end
    if k < 3 then
      a = a + j
    elseif k < 6 then
      b = b + i
    elseif k == 7 then
      c = c + 1
    else
      d = d + k
    end
  end
  a = a & 1048575
  b = b & 1048575
  d = d & 1048575
end
result = a + b + c + d
print(result)
