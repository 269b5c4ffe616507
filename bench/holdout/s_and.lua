-- s_and.st (and p_and.pdl) in Lua 5.4, the same computation; prints the checksum (3135008).
local cnt = 0
for nn = 1, 20000 do
  local xx = nn
  while xx > 0 and cnt < 2000000000 do
    xx = xx - 64
    cnt = cnt + 1
  end
end
result = cnt
print(result)
