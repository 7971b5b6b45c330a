# tests/tum_like.awk: a TUM RGB-D-like ground-truth trajectory, seeded
# (`awk -v n=300 -v seed=7 -f tests/tum_like.awk`): lines
# "timestamp tx ty tz qx qy qz qw" with epoch stamps and positions and
# quaternions to 4 decimals, as the TUM files are written. About 30 Hz with
# jitter (spacings 0.7/30 .. 1.3/30 s) and dropped frames (one in 25 spacings
# doubled); a hand-held motion: position and orientation a sum of slow sines
# (0.05 .. 0.4 Hz, 0.3 m, 0.6 rad) with tremor (1 mm, 3 mrad of white noise
# per key); the quaternion's sign flipped on one key in 8 at random. The
# generator is a Lehmer LCG (48271, mod 2^31 - 1), exact in awk's doubles,
# so every awk gives the same file.
function rnd() { state = (state * 48271) % 2147483647; return state / 2147483647 }
function gauss(   u, v) { u = rnd(); v = rnd(); return sqrt(-2 * log(u + 1e-300)) * cos(6.283185307179586 * v) }
BEGIN {
    if (n == "") n = 300
    state = seed == "" ? 12345 : seed + 1
    for (k = 1; k <= 9; k++) { f[k] = 0.05 + 0.35 * rnd(); ph[k] = 6.283185307179586 * rnd() }
    ticks = 0 # time in 1e-4 s from the first stamp
    for (i = 0; i < n; i++) {
        if (i) ticks += int(10000 / 30 * (0.7 + 0.6 * rnd()) * (rnd() < 0.04 ? 2 : 1) + 0.5)
        t = ticks / 10000
        x = 0.3 * sin(6.283185307179586 * f[1] * t + ph[1]) + 0.001 * gauss()
        y = 0.3 * sin(6.283185307179586 * f[2] * t + ph[2]) + 0.001 * gauss()
        z = 1.2 + 0.1 * sin(6.283185307179586 * f[3] * t + ph[3]) + 0.001 * gauss()
        # roll, pitch, yaw (rad), then the quaternion of Rz(yaw) Ry(pitch) Rx(roll)
        r = 0.6 * sin(6.283185307179586 * f[4] * t + ph[4]) + 0.003 * gauss()
        p = 0.6 * sin(6.283185307179586 * f[5] * t + ph[5]) + 0.003 * gauss()
        w = 0.6 * sin(6.283185307179586 * f[6] * t + ph[6]) + 1.5 * t / 10 + 0.003 * gauss()
        cr = cos(r / 2); sr = sin(r / 2); cp = cos(p / 2); sp = sin(p / 2); cw = cos(w / 2); sw = sin(w / 2)
        qw = cw * cp * cr + sw * sp * sr; qx = cw * cp * sr - sw * sp * cr
        qy = cw * sp * cr + sw * cp * sr; qz = sw * cp * cr - cw * sp * sr
        sg = rnd() < 0.125 ? -1 : 1
        tot = 1758 + ticks
        printf "%d.%04d %.4f %.4f %.4f %.4f %.4f %.4f %.4f\n", 1305031102 + int(tot / 10000), tot % 10000,
            x, y, z, sg * qx, sg * qy, sg * qz, sg * qw
    }
}
