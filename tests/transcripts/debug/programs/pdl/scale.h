// Procedures for pdl_debug.pdl: scale multiplies and doubles through twice, whose frame stands
// above scale's on task 1's stack.
proc twice(long x, long* out) do
#long t;
    t = x * 2;
*out = t;
end;
proc scale(long v, long k, long* res) do
#long prod;
#float half;
    prod = v * k;
twice(prod, &prod);
half = prod / 2;
*res = prod;
end;
