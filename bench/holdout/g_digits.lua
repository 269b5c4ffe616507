-- g_digits.ehl in Lua 5.4, the same computation; prints the checksum (799987).
local tot, n = 0, 1
while n <= 400000 do
  local m, ds = n, 0
  while m > 0 and ds < 1000 do
    ds = ds + m % 10
    m = m // 10
  end
  tot = (tot + ds * (n % 7)) % 1000000
  n = n + 1
end
result = tot
print(result)
