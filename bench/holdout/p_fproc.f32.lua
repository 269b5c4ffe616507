-- p_fproc in float32 arithmetic, as the drive computes it: the checksum uprog must print (not
-- timed), in uprog_bench's format for a float (%.9g).
local function f(v) return (string.unpack("f", string.pack("f", v))) end
local t, b, tot = f(0.001), f(10.0), 0.0
for _ = 1, 300000 do
  local d = f(b - tot)
  d = f(d * t)
  tot = f(d + tot)
end
print(string.format("%.9g", tot))
