-- bench/peers/arrays.lua with 380 elements (what PDL's 400-word user memory holds beside the
-- counters, arrays380.pdl): 3000 rounds of fill a[i]=(i*7919+round)%380, then sum, min and
-- max; the checksum below 1000000.
local a = {}
for i = 0, 379 do a[i] = 0 end
local total = 0
for r = 1, 3000 do
  for i = 0, 379 do
    a[i] = (i * 7919 + r) % 380
  end
  local s, mn, mx = 0, a[0], a[0]
  for i = 0, 379 do
    local v = a[i]
    s = s + v
    if v < mn then mn = v end
    if v > mx then mx = v end
  end
  total = (total + s + mn + mx) % 1000000
end
result = total
print(result)
