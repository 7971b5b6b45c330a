/* tools/columns.h: --columns (docs/tool.md, "Columns"), what `garotor
 * interp` and `garotor eval` share: poses in any column layout, a CSV with a
 * header row read by name (quoted fields as RFC 4180 quotes them; columns
 * that are not read may hold anything, such as a frame id), read into the
 * items of a pose file, t x y z qx qy qz qw a line. Prefix col_.
 */
#ifndef GAROTOR_TOOLS_COLUMNS_H
#define GAROTOR_TOOLS_COLUMNS_H

#include "textio.h"

/** The roles, in the order of the items' numbers: t x y z qx qy qz qw. */
enum { COL_ROLES = 8 };

/** Read the poses of path (NULL or "-": standard input) with the layout
 *  list (the text of --columns) into out: 8 numbers an item and its stamp's
 *  text as out->first. cmd names the command in the usage messages
 *  ("garotor CMD: --columns: ..."); ro: --header (the first line skipped,
 *  when the list does not read it as the header) and --max-line. col, when
 *  not NULL, receives each role's column in the file (from 0), to name them
 *  in later messages. 0, or -1 after a message naming the file, the line
 *  and the column. */
int col_read_poses(const char *cmd, const char *path, const char *list, const tio_read_opts *ro,
                   tio_items *out, long col[COL_ROLES]);

/** Check the list of --columns alone (its words, no role twice, every role
 *  given or header), before any file is read: 0, or -1 after the message
 *  col_read_poses would print. */
int col_check_list(const char *cmd, const char *list);

#endif
