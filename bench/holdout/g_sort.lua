-- g_sort.ehl in Lua 5.4, the same computation; prints the checksum.
local a = {}
for i = 0, 399 do a[i] = 0 end
local seed, chk = 12345, 0
for r = 1, 60 do
  for i = 0, 399 do
    seed = (seed * 1103 + 12345) % 65536
    a[i] = seed % 10007
  end
  for i = 1, 399 do
    local key = a[i]
    local j = i - 1
    while j >= 0 do
      if a[j] <= key then break end
      a[j + 1] = a[j]
      j = j - 1
    end
    a[j + 1] = key
  end
  for i = 0, 399 do
    chk = (chk + a[i] * (i + 1)) % 1000003
  end
end
result = chk
print(result)
