/* tools/stamps.c: see stamps.h. */
#include "stamps.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "timetext.h"

int st_time_unit(const char *cmd, const char *text, int *ns)
{
    *ns = text && strcmp(text, "ns") == 0;
    if (text && !*ns && strcmp(text, "s") != 0) {
        fprintf(stderr, "garotor %s: --time-unit must be s or ns, not '%s'\n", cmd, text);
        return -1;
    }
    return 0;
}

int st_guess_unit(const tio_items *f, size_t i)
{
    static tt_dec t;
    tt_parse(f->first[i], &t);
    int digits = t.n + t.exp; /* of a whole number */
    if (!tt_is_integer(&t) || digits < 12)
        return 0;
    const char *unit = digits >= 18 ? "nanoseconds" : digits >= 15 ? "microseconds" : "milliseconds";
    return tio_error(f, i, "the time %s looks like %s (a whole number of %d digits): %s", f->first[i], unit,
                     digits,
                     digits >= 18 ? "pass --time-unit ns (or --time-unit s if it is seconds)"
                                  : "--time-unit takes s or ns: convert the times (or pass --time-unit s if "
                                    "they are seconds)");
}

int st_whole_ns(const tio_items *f, size_t i)
{
    static tt_dec t;
    tt_parse(f->first[i], &t);
    return tt_is_integer(&t)
             ? 0
             : tio_error(f, i, "--time-unit ns takes whole nanoseconds, not '%s'", f->first[i]);
}

int st_kitti_stamps(const char *path, size_t max_line, int ns, int guess, tio_items *poses)
{
    tio_items s = {0};
    tio_read_opts ro = {0, 0, max_line};
    static tt_dec a, b, d;
    int rc = -1;
    if (tio_read_first(path, &ro, &s))
        goto done;
    for (size_t k = 0; k < s.n; k++) {
        if (s.item[k].count != 1) {
            tio_error(&s, k, "expected 1 number (a stamp of --stamps: KITTI's times.txt), found %d",
                      s.item[k].count);
            goto done;
        }
        if ((k == 0 && guess && st_guess_unit(&s, 0)) || (ns && st_whole_ns(&s, k)))
            goto done;
        tt_parse(s.first[k], &b);
        if (k > 0 && tt_add(&b, &a, 1, &d) == 0 && (d.n == 0 || d.neg)) {
            tio_error(&s, k, "stamps must increase strictly: %s after %s", s.first[k], s.first[k - 1]);
            goto done;
        }
        a = b;
    }
    if (s.n > poses->n) {
        tio_error(&s, poses->n,
                  "stamp %zu has no pose: %s has %zu poses, %s %zu stamps (one a pose, in order)",
                  poses->n + 1, poses->name, poses->n, s.name, s.n);
        goto done;
    }
    if (s.n < poses->n) {
        if (s.n == 0)
            fprintf(stderr, "garotor: %s: no stamps (--stamps: one a pose of %s, in order)\n", s.name,
                    poses->name);
        else
            tio_error(poses, s.n,
                      "pose %zu has no stamp: %s has %zu stamps, %s %zu poses (one a pose, in order)",
                      s.n + 1, s.name, s.n, poses->name, poses->n);
        goto done;
    }
    for (size_t k = 0; k < s.n; k++) { /* the stamp's text is the pose's */
        free(poses->first[k]);
        poses->first[k] = s.first[k];
        s.first[k] = NULL;
    }
    rc = 0;
done:
    tio_free(&s);
    return rc;
}
