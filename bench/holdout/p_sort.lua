-- p_sort.pdl in Lua 5.4, the same computation; prints the checksum.
local a = {}
for i = 0, 299 do a[i] = 0 end
local seed, chk = 12345, 0
for r = 1, 100 do
  for i = 0, 299 do
    seed = (seed * 1103 + 12345) % 65536
    a[i] = seed % 10007
  end
  for i = 0, 298 do
    local n1 = 299 - i
    for j = 0, n1 - 1 do
      local t, u = a[j], a[j + 1]
      if t > u then
        a[j] = u
        a[j + 1] = t
      end
    end
  end
  for i = 0, 299 do
    chk = (chk + (i + 1) * a[i]) % 1000003
  end
end
result = chk
print(result)
