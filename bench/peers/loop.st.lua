-- bench/peers/loop.st in Lua 5.4, the same computation: the remainders kept as counters, as ST
-- must keep them (its MOD refuses a quotient beyond 16 bits: 30 million / 3 is one). The
-- checksum is loop.lua's, 59999995; the counters are locals, Lua's fastest variables.
local s, r3, r7 = 0, 0, 0
for _ = 1, 30000000 do
  r3 = r3 + 1
  if r3 == 3 then
    r3 = 0
  end
  r7 = r7 + 1
  if r7 == 7 then
    r7 = 0
  end
  if r3 ~= 0 then
    s = s + r7
  end
end
result = s
print(result)
