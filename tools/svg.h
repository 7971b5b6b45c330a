/* tools/svg.h: pictures of moving frames, as hand-written SVG (no dependency).
 *
 * A picture shows one or more paths of a moving frame, each a sequence of 4x4
 * homogeneous matrices M(t):
 *   - the trajectory of the frame's origin (the translation column of M),
 *     projected to 2D by a fixed orthographic view (svg_view);
 *   - small coordinate frames, the columns of M's 3x3 block drawn from the
 *     origin (x red, y green, z blue), at the keys and at regular samples;
 *   - a dashed screw axis, when the motion is a single screw (svg_screw_axis).
 * The scene is scaled to fit, the same scale across and up, so angles and
 * lengths in the plane of the view are true. Coordinates are written with two
 * decimals, so the same input gives the same bytes.
 *
 * The file is written to a temporary name beside it and renamed when complete
 * and the caller's other outputs are written too (tio_out), so a failure
 * leaves nothing behind.
 */
#ifndef GAROTOR_TOOLS_SVG_H
#define GAROTOR_TOOLS_SVG_H

#include <stddef.h>

#include <garotor/garotor.h>

#include "textio.h"

/** The view: orthographic, looking from (1, 1, 1) towards the origin with z up
 *  (iso), or down an axis: xy (from +z, x right, y up), xz (from -y, x right,
 *  z up), yz (from +x, y right, z up). */
typedef enum { SVG_VIEW_ISO, SVG_VIEW_XY, SVG_VIEW_XZ, SVG_VIEW_YZ } svg_view;

/** One path of the moving frame. */
typedef struct {
    const char *label;     /**< legend text, or NULL */
    const char *colour;    /**< trajectory colour (an SVG colour, e.g. "#222222") */
    const ga_mat4 *sample; /**< the samples, drawn in this order */
    size_t n;
    int frames; /**< about how many frames to draw along it (0: none) */
} svg_path;

/** A picture. */
typedef struct {
    const char *title; /**< one line of text at the top */
    svg_view view;
    const ga_mat4 *key;  /**< keys: bold frames with a dot */
    const double *key_t; /**< their times (labels), or NULL */
    size_t nkeys;
    const svg_path *path;
    size_t npaths;
    int has_axis; /**< draw the screw axis below */
    ga_vec3 axis_point, axis_dir;
} svg_picture;

/** The view called name ("iso", "xy", "xz", "yz"); -1 if there is none. */
int svg_view_by_name(const char *name, svg_view *out);
/** "iso", "xy", "xz" or "yz". */
const char *svg_view_name(svg_view v);

/** If the n >= 2 keys (rigid motions) lie on one screw motion, i.e. every
 *  relative motion M_{i+1} M_i^-1 has its principal screw (ga_rotor_to_screw)
 *  about the same axis line, in the same sense, with the same pitch and a
 *  nonzero angle (to 1e-9), write a point of that axis and its unit direction
 *  and return 1; else (pure translations included) return 0. */
int svg_screw_axis(const ga_mat4 *key, size_t n, ga_vec3 *point, ga_vec3 *dir);

/** The --svg and --view options of a command: checks that --svg names a file
 *  (not "-") and --view a view, and that --view comes with --svg; writes the
 *  view (default iso). 0, or -1 after a message "garotor CMD: ...". */
int svg_options(const char *cmd, const char *svg, const char *view, svg_view *out);

/** Write the picture to file, through out: to its temporary file, finished
 *  but not renamed (tio_out_finish), so that the caller renames it with
 *  tio_out_commit once its other outputs are written, or removes it with
 *  tio_out_discard. 0 on success, -1 after a message naming the file
 *  (nothing left). */
int svg_write(tio_out *out, const char *file, const svg_picture *pic);

#endif
