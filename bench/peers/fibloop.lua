-- fib(27) = 196418 as a loop, 200 000 times (bench/peers/fibloop.pup); prints the checksum.
local result = 0
for round = 1, 200000 do
  local a, b = 0, 1
  for k = 1, 27 do
    local t = a + b
    a = b
    b = t
  end
  result = a
end
print(result)
