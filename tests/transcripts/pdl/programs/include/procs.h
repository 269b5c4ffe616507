// Included by common.h (found beside it): a procedure.
proc add_to(long v, long* p) do* p += v;
*p += LIMIT;
end;
