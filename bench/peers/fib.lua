-- Recursive fib(27); prints the checksum (196418).
local function fib(n)
  if n < 2 then return n end
  return fib(n - 1) + fib(n - 2)
end
result = fib(27)
print(result)
