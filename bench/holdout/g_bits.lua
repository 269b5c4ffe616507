-- g_bits.ehl in Lua 5.4, the same computation; prints the checksum.
local x, acc, i = 1234567, 0, 0
while i < 2000000 do
  local y = (x << 3) & 16777215
  x = (x | y) & ~(x & y)
  y = x >> 5
  x = (x | y) & ~(x & y)
  local h = (x & 255) + ((x >> 8) & 255) + (x >> 16)
  if h % 3 == 0 then
    acc = acc + h
  else
    acc = acc + (x % 97)
  end
  acc = acc & 1048575
  i = i + 1
end
result = acc
print(result)
