/* tools/html.h: a self-contained web page of moving frames, turned with the
 * mouse (no network, no dependency: one file, an inline script drawing on a
 * canvas with its 2D context).
 *
 * The page holds the same scene as an SVG picture (svg.h): the trajectory of
 * each path's origin, small frames along it (x red, y green, z blue) and the
 * keys. The script projects it orthographically from a direction the mouse
 * turns (drag: azimuth and elevation), and writes its state into the page:
 * <body data-state="drawn"> once drawn, data-error="..." on any script error,
 * so that a headless browser's --dump-dom tells whether it rendered
 * (tests/html_test.sh). Numbers are written with %.9g, so the same input
 * gives the same bytes.
 */
#ifndef GAROTOR_TOOLS_HTML_H
#define GAROTOR_TOOLS_HTML_H

#include "svg.h"

/** The --html option of a command: checks that it names a file (not "-").
 *  0, or -1 after a message "garotor CMD: ...". */
int html_options(const char *cmd, const char *html);

/** Write the picture (keys, paths; view and axis unused: the page turns) to file
 *  as a web page, through out, finished but not renamed, as svg_write does.
 *  0, or -1 after a message. */
int html_write(tio_out *out, const char *file, const svg_picture *pic);

#endif
