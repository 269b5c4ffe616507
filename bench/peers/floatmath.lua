-- 3 million iterations of x = x + sin(i*0.001)*sqrt(i), in double; prints the checksum.
local sin, sqrt = math.sin, math.sqrt
local x = 0.0
for i = 1, 3000000 do
  x = x + sin(i * 0.001) * sqrt(i)
end
result = x
print(string.format("%.17g", result))
