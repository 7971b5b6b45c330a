/* tools/stamps.h: what `garotor interp` and `garotor eval` share about the
 * stamps of their poses (docs/tool.md, "Times" and "garotor eval"): the
 * option --time-unit, the unit a stamp looks like when it is not given, and
 * --stamps FILE, the stamps of KITTI poses (which have none) read from
 * KITTI's times.txt. Prefix st_.
 */
#ifndef GAROTOR_TOOLS_STAMPS_H
#define GAROTOR_TOOLS_STAMPS_H

#include <stddef.h>

#include "textio.h"

/** --time-unit TEXT of command cmd (TEXT NULL: not given): *ns 1 for "ns",
 *  0 for "s" or none; -1 after "garotor CMD: --time-unit must be s or ns". */
int st_time_unit(const char *cmd, const char *text, int *ns);

/** With no --time-unit: the stamp of item i (its first number's text) a
 *  whole number of 12 digits or more is an error naming the line and what
 *  it looks like (epoch milliseconds, microseconds or nanoseconds, which read
 *  as seconds would make every rate per ms, us or ns). 0, or -1 after the
 *  message. */
int st_guess_unit(const tio_items *f, size_t i);

/** With --time-unit ns: the stamp of item i must be a whole number. 0, or
 *  -1 after a message naming the line. */
int st_whole_ns(const tio_items *f, size_t i);

/** --stamps FILE: KITTI's times.txt, one stamp a line (`#` and blank lines
 *  skipped), strictly increasing, whole numbers with ns (st_whole_ns), the
 *  first checked by st_guess_unit with guess; as many as poses has items;
 *  each item's first text (poses->first, from tio_read_first) becomes its
 *  stamp's text. A count that differs is an error naming the first line
 *  without its partner: the first pose with no stamp, or the first stamp
 *  with no pose. max_line: --max-line (0: the default). 0, or -1 after a
 *  message naming the line. */
int st_kitti_stamps(const char *path, size_t max_line, int ns, int guess, tio_items *poses);

#endif
