# docs/ros-export.awk: the tutorial's ROS export pair (docs/make-figures.sh),
# from poses the tool sampled on one path (TUM lines: t x y z qx qy qz qw, t
# in whole nanoseconds). Plain POSIX awk; the noise comes from Park and
# Miller's minimal standard generator (x <- 16807 x mod 2^31 - 1: every
# product below 2^53, so exact in any awk), seeded, so the files are the
# same on every machine.
#
#   awk -v what=stamps -v seed=S            the estimate's stamps (ns), about 30 Hz
#   awk -v what=gt -v seed=S FILE           ground truth as `rostopic echo -p` writes it
#   awk -v what=est -v seed=S FILE          the estimate: another frame, a yaw drift,
#                                           noise, written as pandas writes a CSV
#                                           (to_csv(quoting=csv.QUOTE_NONNUMERIC))
function rnd() { seed = (seed * 16807) % 2147483647; return seed / 2147483647 }
function noise() { return rnd() + rnd() + rnd() + rnd() - 2 } # mean 0, sd 0.577
# a stamp of 19 digits plus ns >= 0 nanoseconds, as text: seconds and
# nanoseconds kept apart, each exact in a double
function later(t, ns,   s, n) {
    s = substr(t, 1, length(t) - 9) + 0; n = substr(t, length(t) - 8) + ns
    s += int(n / 1000000000); n %= 1000000000
    return sprintf("%d%09d", s, n)
}
# q = a b (x y z w)
function qmul(ax, ay, az, aw, bx, by, bz, bw) {
    qx = aw * bx + ax * bw + ay * bz - az * by
    qy = aw * by - ax * bz + ay * bw + az * bx
    qz = aw * bz + ax * by - ay * bx + az * bw
    qw = aw * bw - ax * bx - ay * by - az * bz
}
BEGIN {
    if (what == "stamps") { # from 17.3 ms after the first key to 9.95 s, 1/30 s apart, +-3 ms
        for (k = 0; k < 298; k++)
            print later("1700000000000000000", 17300000 + int(k * 33333333.33) + int(6000000 * rnd()) - 3000000)
        exit
    }
    if (what == "gt")
        print "%time,field.header.seq,field.header.stamp,field.header.frame_id,field.pose.position.x," \
              "field.pose.position.y,field.pose.position.z,field.pose.orientation.x," \
              "field.pose.orientation.y,field.pose.orientation.z,field.pose.orientation.w"
    else
        print "\"%time\",\"field.header.seq\",\"field.header.stamp\",\"field.header.frame_id\"," \
              "\"field.pose.position.x\",\"field.pose.position.y\",\"field.pose.position.z\"," \
              "\"field.pose.orientation.x\",\"field.pose.orientation.y\",\"field.pose.orientation.z\"," \
              "\"field.pose.orientation.w\""
}
what == "gt" { # recorded 2 to 3 ms after the pose was taken; micrometres
    printf "%s,%d,%s,world,%.6f,%.6f,%.6f,%.12g,%.12g,%.12g,%.12g\n", later($1, 2000000 + int(1000000 * rnd())),
        NR - 1, $1, $2, $3, $4, $5, $6, $7, $8
}
what == "est" { # the odometry frame: turned 0.5 rad about z, moved, drifting in yaw 0.01 rad/s
    dt = (substr($1, length($1) - 9) + 0) / 1e9
    a = 0.5 + 0.01 * dt; c = cos(a); s = sin(a)
    x = c * $2 - s * $3 + 0.8 + 0.015 * noise(); y = s * $2 + c * $3 - 1.2 + 0.015 * noise()
    z = $4 + 0.05 + 0.015 * noise()
    qmul(0, 0, sin(a / 2), cos(a / 2), $5, $6, $7, $8)
    ex = 0.003 * noise(); ey = 0.003 * noise(); ez = 0.003 * noise() # about 0.1 degree a side
    qmul(qx, qy, qz, qw, ex, ey, ez, 1)
    n = sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    printf "%s,%d,%s,\"odom\",%.6f,%.6f,%.6f,%.12g,%.12g,%.12g,%.12g\n", later($1, 4000000 + int(2000000 * rnd())),
        NR - 1, $1, x, y, z, qx / n, qy / n, qz / n, qw / n
}
