-- s_while.st in Lua 5.4, the same computation; prints the checksum.
local nn, va, vb, vc, vd, ve, vf, vg = 0, 1, 2, 3, 4, 5, 6, 0
while nn < 2000000 do
  va = (va + vb) & 65535
  vb = (vb + vc + 1) & 65535
  vc = (vc - va + vd) & 65535
  vd = (vd + (ve >> 2)) & 65535
  ve = (ve + va * 3) & 65535
  vf = vf + (va ~ ve)
  vf = vf & 16777215
  vg = vg + ((vb | vc) & 255)
  nn = nn + 1
end
result = vf + vg + va + vb + vc + vd + ve
print(result)
