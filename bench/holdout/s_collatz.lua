-- s_collatz.st in Lua 5.4, the same computation; prints the checksum.
local total, maxs = 0, 0
for nn = 1, 30000 do
  local xx, steps = nn, 0
  while xx ~= 1 do
    if xx & 1 ~= 0 then
      xx = xx + xx + xx + 1
    else
      xx = xx >> 1
    end
    steps = steps + 1
  end
  total = total + steps
  if steps > maxs then maxs = steps end
end
result = total + maxs
print(result)
