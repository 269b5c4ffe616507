-- 30 million iterations summing i%7 for every i not divisible by 3; prints the checksum.
local s = 0
for i = 1, 30000000 do
  if i % 3 ~= 0 then
    s = s + i % 7
  end
end
result = s
print(result)
