-- u_sieve.pup in Lua 5.4, the same computation; prints the checksum.
local flag = {}
for i = 1, 900 do flag[i] = 0 end
local chk = 0
for r = 1, 4000 do
  for i = 1, 900 do flag[i] = 1 end
  flag[1] = 0
  local i = 2
  while i * i <= 900 do
    if flag[i] ~= 0 then
      for j = i * i, 900, i do flag[j] = 0 end
    end
    i = i + 1
  end
  local cnt, sm = 0, 0
  for i = 1, 900 do
    if flag[i] ~= 0 then
      cnt = cnt + 1
      sm = sm + i
    end
  end
  chk = (chk + cnt + sm + r) % 1000000
end
result = chk
print(result)
