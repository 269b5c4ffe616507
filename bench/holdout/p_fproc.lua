-- bench/holdout/p_fproc.pdl in Lua 5.4: the same procedure as a function returning its result.
local function lerp(a, b, t)
  local d = b - a
  d = d * t
  d = d + a
  return d
end
local tot = 0.0
for _ = 1, 300000 do tot = lerp(tot, 10.0, 0.001) end
result = tot
print(result)
