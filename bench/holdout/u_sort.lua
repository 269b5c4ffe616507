-- u_sort.pup in Lua 5.4, the same computation; prints the checksum.
local a = {}
for i = 0, 500 do a[i] = 0 end
local seed, chk = 12345, 0
for r = 1, 100 do
  for i = 1, 500 do
    seed = (seed * 1103 + 12345) % 65536
    a[i] = seed % 10007
  end
  for i = 2, 500 do
    local key = a[i]
    local j = i - 1
    while j >= 1 and a[j] > key do
      a[j + 1] = a[j]
      j = j - 1
    end
    a[j + 1] = key
  end
  for i = 1, 500 do
    chk = (chk + a[i] * i) % 1000003
  end
end
result = chk
print(result)
