-- bench/holdout/p_ploop.pdl in Lua 5.4: the procedure as a function returning its sum.
local function sumto(n)
  local i, s = 0, 0
  while i < n do
    s = s + i
    i = i + 1
  end
  return s
end
local tot = 0
for _ = 1, 1000 do tot = tot + sumto(1000) end
result = tot
print(result)
