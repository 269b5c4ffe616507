-- 2 million 50 us cycles of a trapezoidal point-to-point generator (double): accelerate to
-- vmax, decelerate when the stopping distance reaches the target, then pick a new target from
-- an LCG. Prints `moves` (moves finished) and `result` (sum of targets reached + position).
local dt, acc, vmax = 0.00005, 200000.0, 5000.0
local dv = acc * dt
local seed, tgt, pos, spd, sum, n = 1, 500.0, 0.0, 0.0, 0.0, 0
for _ = 1, 2000000 do
  local d = tgt - pos
  local dir
  if d >= 0.0 then
    dir = 1.0
  else
    dir = -1.0
    d = -d
  end
  if d <= spd * spd / (2.0 * acc) then
    spd = spd - dv
    if spd < 0.0 then spd = 0.0 end
  elseif spd < vmax then
    spd = spd + dv
    if spd > vmax then spd = vmax end
  end
  local step = spd * dt
  if step >= d then
    pos = tgt
    spd = 0.0
    n = n + 1
    sum = sum + tgt
    seed = (seed * 75 + 74) % 65537
    tgt = seed % 2000 - 1000
  else
    pos = pos + dir * step
  end
end
moves = n
result = sum + pos
print(moves, string.format("%.17g", result))
