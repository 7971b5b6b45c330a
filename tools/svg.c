/* tools/svg.c: see svg.h. */
#include "svg.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <garotor/numtext.h>
#include "textio.h"

/* ---- small vector helpers ------------------------------------------------ */

static ga_vec3 vec(double x, double y, double z) { return (ga_vec3){x, y, z}; }
static double dot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ga_vec3 axpy(double s, ga_vec3 a, ga_vec3 b) /* s a + b */
{
    return vec(s * a.x + b.x, s * a.y + b.y, s * a.z + b.z);
}
static ga_vec3 cross(ga_vec3 a, ga_vec3 b)
{
    return vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static ga_vec3 origin_of(const ga_mat4 *m) { return vec(m->m[3], m->m[7], m->m[11]); }
static ga_vec3 column(const ga_mat4 *m, int j) { return vec(m->m[j], m->m[4 + j], m->m[8 + j]); }

/* ---- views --------------------------------------------------------------- */

static const char *const view_names[] = {"iso", "xy", "xz", "yz"};

int svg_view_by_name(const char *name, svg_view *out)
{
    for (int v = 0; v < 4; v++)
        if (strcmp(name, view_names[v]) == 0) {
            *out = (svg_view)v;
            return 0;
        }
    return -1;
}

const char *svg_view_name(svg_view v) { return view_names[v]; }

int svg_options(const char *cmd, const char *svg, const char *view, svg_view *out)
{
    *out = SVG_VIEW_ISO;
    if (view && !svg) {
        fprintf(stderr, "garotor %s: --view applies only with --svg FILE\n", cmd);
        return -1;
    }
    if (svg && (svg[0] == '\0' || strcmp(svg, "-") == 0)) {
        fprintf(stderr, "garotor %s: --svg needs a file name, not '%s'\n", cmd, svg);
        return -1;
    }
    if (view && svg_view_by_name(view, out)) {
        fprintf(stderr, "garotor %s: --view must be iso, xy, xz or yz, not '%s'\n", cmd, view);
        return -1;
    }
    return 0;
}

/* The screen's right, up and out-of-screen directions in world coordinates
 * (a right-handed triple: right x up = out). */
static void view_basis(svg_view v, ga_vec3 *right, ga_vec3 *up, ga_vec3 *out)
{
    switch (v) {
    case SVG_VIEW_ISO:
        *right = vec(-sqrt(0.5), sqrt(0.5), 0);
        *up = vec(-1 / sqrt(6.0), -1 / sqrt(6.0), 2 / sqrt(6.0));
        *out = vec(1 / sqrt(3.0), 1 / sqrt(3.0), 1 / sqrt(3.0));
        break;
    case SVG_VIEW_XY:
        *right = vec(1, 0, 0);
        *up = vec(0, 1, 0);
        *out = vec(0, 0, 1);
        break;
    case SVG_VIEW_XZ:
        *right = vec(1, 0, 0);
        *up = vec(0, 0, 1);
        *out = vec(0, -1, 0);
        break;
    case SVG_VIEW_YZ:
        *right = vec(0, 1, 0);
        *up = vec(0, 0, 1);
        *out = vec(1, 0, 0);
        break;
    }
}

/* ---- the screw axis ------------------------------------------------------ */

int svg_screw_axis(const ga_mat4 *key, size_t n, ga_vec3 *point, ga_vec3 *dir)
{
    ga_screw first = {0};
    for (size_t i = 0; i + 1 < n; i++) {
        ga_rotor a, b;
        ga_screw s;
        if (ga_rotor_from_mat4(key[i], &a) != GA_OK || ga_rotor_from_mat4(key[i + 1], &b) != GA_OK ||
            ga_rotor_to_screw(ga_rotor_mul(b, ga_rotor_reverse(a)), &s) != GA_OK || !(s.angle > 0.0))
            return 0;
        if (i == 0) {
            first = s;
            continue;
        }
        /* same sense, same line (s.point's distance from it), same pitch */
        ga_vec3 d = axpy(-1.0, first.point, s.point);
        double size = fmax(1.0, fmax(sqrt(dot(first.point, first.point)), sqrt(dot(s.point, s.point))));
        ga_vec3 off = cross(d, first.axis);
        if (dot(s.axis, first.axis) <= 0.0 ||
            sqrt(dot(cross(s.axis, first.axis), cross(s.axis, first.axis))) > 1e-9 ||
            sqrt(dot(off, off)) > 1e-9 * size ||
            fabs(s.pitch - first.pitch) > 1e-9 * fmax(1.0, fabs(first.pitch)))
            return 0;
    }
    if (n < 2)
        return 0;
    *point = first.point;
    *dir = first.axis;
    return 1;
}

/* ---- drawing --------------------------------------------------------------- */

enum { WIDTH = 800, MARGIN = 24, TITLE_H = 40, LEGEND_H = 48, KEYS_SHOWN = 10 };

static const char *const axis_colour[3] = {"#d62728", "#2ca02c", "#1f77b4"};
static const char key_colour[] = "#000000", screw_colour[] = "#8c564b";

typedef struct {
    FILE *f;
    ga_vec3 right, up, out;
    double scale, x0, y0; /* screen = (x0 + scale right.p, y0 - scale up.p) */
    double frame_len;     /* length of a frame's axes, world units */
} canvas;

/* A number with two decimals, never "-0.00" (so output bytes are stable). */
static void num(FILE *f, double v)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.2f", v);
    fputs(strcmp(buf, "-0.00") == 0 ? "0.00" : buf, f);
}

static void point_xy(const canvas *c, ga_vec3 p, double *x, double *y)
{
    *x = c->x0 + c->scale * dot(c->right, p);
    *y = c->y0 - c->scale * dot(c->up, p);
}

static void text(FILE *f, const char *s)
{
    for (; *s; s++) switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
}

static void line(FILE *f, double x1, double y1, double x2, double y2, const char *colour)
{
    fputs("<line x1=\"", f);
    num(f, x1);
    fputs("\" y1=\"", f);
    num(f, y1);
    fputs("\" x2=\"", f);
    num(f, x2);
    fputs("\" y2=\"", f);
    num(f, y2);
    fprintf(f, "\" stroke=\"%s\"/>\n", colour);
}

/* A frame: its three axes from the origin, the ones pointing away drawn first. */
static void frame(const canvas *c, const ga_mat4 *m)
{
    ga_vec3 o = origin_of(m);
    int order[3] = {0, 1, 2};
    double depth[3];
    for (int j = 0; j < 3; j++) depth[j] = dot(c->out, column(m, j));
    for (int a = 0; a < 3; a++)
        for (int b = a + 1; b < 3; b++)
            if (depth[order[b]] < depth[order[a]]) {
                int t = order[a];
                order[a] = order[b];
                order[b] = t;
            }
    double x0, y0;
    point_xy(c, o, &x0, &y0);
    for (int k = 0; k < 3; k++) {
        double x1, y1;
        point_xy(c, axpy(c->frame_len, column(m, order[k]), o), &x1, &y1);
        line(c->f, x0, y0, x1, y1, axis_colour[order[k]]);
    }
}

/* The indices of about `frames` evenly spread samples of n (first and last
 * included): the k-th is round(k (n - 1) / frames). */
static size_t frame_index(size_t n, int frames, int k)
{
    return (size_t)floor((double)k * (double)(n - 1) / frames + 0.5);
}

/* The bounding box of everything drawn, in world units projected on the
 * screen's right and up directions. */
typedef struct {
    double lo[2], hi[2];
} box2;

static void box_add(box2 *b, const canvas *c, ga_vec3 p)
{
    double v[2] = {dot(c->right, p), dot(c->up, p)};
    for (int i = 0; i < 2; i++) {
        b->lo[i] = fmin(b->lo[i], v[i]);
        b->hi[i] = fmax(b->hi[i], v[i]);
    }
}

static void box_add_frame(box2 *b, const canvas *c, const ga_mat4 *m)
{
    ga_vec3 o = origin_of(m);
    box_add(b, c, o);
    for (int j = 0; j < 3; j++) box_add(b, c, axpy(c->frame_len, column(m, j), o));
}

/* Every frame origin (keys and samples): its 3D bounding box centre and diagonal. */
static void scene_extent(const svg_picture *pic, ga_vec3 *centre, double *diag)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t p = 0; p <= pic->npaths; p++) {
        const ga_mat4 *m = p < pic->npaths ? pic->path[p].sample : pic->key;
        size_t n = p < pic->npaths ? pic->path[p].n : pic->nkeys;
        for (size_t i = 0; i < n; i++) {
            double o[3] = {m[i].m[3], m[i].m[7], m[i].m[11]};
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], o[k]);
                hi[k] = fmax(hi[k], o[k]);
            }
        }
    }
    if (!(lo[0] <= hi[0])) { /* nothing at all */
        *centre = vec(0, 0, 0);
        *diag = 0.0;
        return;
    }
    *centre = vec((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    *diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                 (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

static void legend_line(FILE *f, double *x, double y, const char *colour, const char *dash, const char *label)
{
    fputs("<line x1=\"", f);
    num(f, *x);
    fputs("\" y1=\"", f);
    num(f, y);
    fputs("\" x2=\"", f);
    num(f, *x + 22);
    fputs("\" y2=\"", f);
    num(f, y);
    fprintf(f, "\" stroke=\"%s\" stroke-width=\"2.5\"%s/>\n", colour, dash);
    fputs("<text x=\"", f);
    num(f, *x + 27);
    fputs("\" y=\"", f);
    num(f, y + 4);
    fputs("\">", f);
    text(f, label);
    fputs("</text>\n", f);
    *x += 27 + 7.0 * (double)strlen(label) + 16;
}

/* The canvas (view, frame length, scale and origin) that fits everything
 * drawn, and the ends a, b of the screw axis's segment; returns the
 * picture's height. */
static int layout(const svg_picture *pic, canvas *c, ga_vec3 *axis_a, ga_vec3 *axis_b)
{
    view_basis(pic->view, &c->right, &c->up, &c->out);
    ga_vec3 centre;
    double diag;
    scene_extent(pic, &centre, &diag);
    c->frame_len = diag > 0.0 ? 0.07 * diag : 1.0;

    /* the screw axis: the segment of it alongside the frame origins, and a
     * little more at each end */
    *axis_a = *axis_b = (ga_vec3){0};
    if (pic->has_axis) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t p = 0; p <= pic->npaths; p++) {
            const ga_mat4 *m = p < pic->npaths ? pic->path[p].sample : pic->key;
            size_t n = p < pic->npaths ? pic->path[p].n : pic->nkeys;
            for (size_t i = 0; i < n; i++) {
                double s = dot(pic->axis_dir, axpy(-1.0, pic->axis_point, origin_of(&m[i])));
                lo = fmin(lo, s);
                hi = fmax(hi, s);
            }
        }
        double margin = 0.15 * diag + c->frame_len;
        *axis_a = axpy(lo - margin, pic->axis_dir, pic->axis_point);
        *axis_b = axpy(hi + margin, pic->axis_dir, pic->axis_point);
    }

    /* fit everything drawn into the plot area, the same scale both ways */
    box2 b = {{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
    for (size_t k = 0; k < pic->nkeys; k++) box_add_frame(&b, c, &pic->key[k]);
    for (size_t p = 0; p < pic->npaths; p++)
        for (size_t i = 0; i < pic->path[p].n; i++) box_add_frame(&b, c, &pic->path[p].sample[i]);
    if (pic->has_axis) {
        box_add(&b, c, *axis_a);
        box_add(&b, c, *axis_b);
    }
    if (!(b.lo[0] <= b.hi[0])) /* nothing to draw */
        b = (box2){{-1, -1}, {1, 1}};
    double bw = fmax(b.hi[0] - b.lo[0], 1e-300), bh = fmax(b.hi[1] - b.lo[1], 1e-300);
    double plot_w = WIDTH - 2 * MARGIN;
    double plot_h = fmin(fmax(plot_w * bh / bw, 240.0), 640.0);
    c->scale = fmin(plot_w / bw, plot_h / bh);
    c->x0 = WIDTH / 2.0 - c->scale * (b.lo[0] + b.hi[0]) / 2;
    c->y0 = TITLE_H + MARGIN / 2.0 + plot_h / 2 + c->scale * (b.lo[1] + b.hi[1]) / 2;
    return (int)(TITLE_H + MARGIN + plot_h + LEGEND_H);
}

/* The trajectories, then the frames along them. */
static void draw_paths(const canvas *c, const svg_picture *pic)
{
    FILE *f = c->f;
    for (size_t p = 0; p < pic->npaths; p++) {
        const svg_path *pa = &pic->path[p];
        fprintf(f,
                "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\" "
                "stroke-linejoin=\"round\" points=\"",
                pa->colour);
        for (size_t i = 0; i < pa->n; i++) {
            double x, y;
            point_xy(c, origin_of(&pa->sample[i]), &x, &y);
            if (i)
                fputc(i % 8 ? ' ' : '\n', f);
            num(f, x);
            fputc(',', f);
            num(f, y);
        }
        fputs("\"/>\n", f);
    }
    fputs("<g stroke-width=\"1.3\" stroke-linecap=\"round\">\n", f);
    for (size_t p = 0; p < pic->npaths; p++) {
        const svg_path *pa = &pic->path[p];
        if (pa->n < 2 || pa->frames <= 0)
            continue;
        size_t last = (size_t)-1;
        for (int k = 0; k <= pa->frames; k++) {
            size_t i = frame_index(pa->n, pa->frames, k);
            if (i != last)
                frame(c, &pa->sample[i]);
            last = i;
        }
    }
    fputs("</g>\n", f);
}

/* The keys, on top: up to KEYS_SHOWN keys, bold frames and labels; more:
 * dots, and labels at the first and last. */
static void draw_keys(const canvas *c, const svg_picture *pic)
{
    FILE *f = c->f;
    int few = pic->nkeys <= KEYS_SHOWN;
    fprintf(f, "<g stroke-width=\"%s\" stroke-linecap=\"round\">\n", few ? "2.6" : "1.3");
    for (size_t k = 0; k < pic->nkeys; k++) frame(c, &pic->key[k]);
    fputs("</g>\n", f);
    for (size_t k = 0; k < pic->nkeys; k++) {
        double x, y;
        point_xy(c, origin_of(&pic->key[k]), &x, &y);
        fputs("<circle cx=\"", f);
        num(f, x);
        fputs("\" cy=\"", f);
        num(f, y);
        fprintf(f, "\" r=\"3.5\" fill=\"%s\"/>\n", key_colour);
        if (pic->key_t && (few || k == 0 || k + 1 == pic->nkeys)) {
            fputs("<text x=\"", f);
            num(f, x + 7);
            fputs("\" y=\"", f);
            num(f, y - 7);
            char tb[GA_DOUBLE_TEXT_MAX]; /* the shortest text of the key's time: t=1305031102.1758,
                                            not 1.30503e+09 */
            ga_double_format(pic->key_t[k], tb);
            fprintf(f, "\">t=%s</text>\n", tb);
        }
    }
}

/* The legend, and the view's world axes in the bottom right corner. */
static void draw_legend(const canvas *c, const svg_picture *pic, int height)
{
    FILE *f = c->f;
    double lx = 12, ly = height - LEGEND_H / 2.0;
    for (size_t p = 0; p < pic->npaths; p++)
        if (pic->path[p].label)
            legend_line(f, &lx, ly, pic->path[p].colour, "", pic->path[p].label);
    if (pic->has_axis)
        legend_line(f, &lx, ly, screw_colour, " stroke-dasharray=\"8 5\"", "screw axis");
    static const char *const names[3] = {"x", "y", "z"};
    fputs("<text x=\"", f);
    num(f, lx);
    fputs("\" y=\"", f);
    num(f, ly + 4);
    fputs("\">frames:</text>\n", f);
    lx += 58;
    for (int j = 0; j < 3; j++) legend_line(f, &lx, ly, axis_colour[j], "", names[j]);
    double tx = WIDTH - 70, ty = height - LEGEND_H / 2.0;
    fputs("<g stroke=\"#555555\" stroke-width=\"1.2\">\n", f);
    for (int j = 0; j < 3; j++) {
        ga_vec3 e = vec(j == 0, j == 1, j == 2);
        double dx = 16 * dot(c->right, e), dy = -16 * dot(c->up, e);
        if (dx * dx + dy * dy < 4)
            continue; /* seen end on */
        line(f, tx, ty, tx + dx, ty + dy, "#555555");
    }
    fputs("</g>\n", f);
    for (int j = 0; j < 3; j++) {
        ga_vec3 e = vec(j == 0, j == 1, j == 2);
        double dx = 16 * dot(c->right, e), dy = -16 * dot(c->up, e);
        if (dx * dx + dy * dy < 4)
            continue;
        fputs("<text text-anchor=\"middle\" x=\"", f);
        num(f, tx + 1.5 * dx);
        fputs("\" y=\"", f);
        num(f, ty + 1.5 * dy + 4);
        fprintf(f, "\" fill=\"#555555\">%s</text>\n", names[j]);
    }
    fputs("<text text-anchor=\"end\" x=\"", f);
    num(f, tx - 24);
    fputs("\" y=\"", f);
    num(f, ty + 4);
    fprintf(f, "\" fill=\"#555555\">view %s</text>\n", svg_view_name(pic->view));
}

int svg_write(tio_out *out, const char *file, const svg_picture *pic)
{
    canvas c = {0};
    ga_vec3 axis_a, axis_b;
    int height = layout(pic, &c, &axis_a, &axis_b);

    if (tio_out_open(out, file))
        return -1;
    FILE *f = c.f = out->fp;
    fprintf(f,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
            "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n",
            WIDTH, height, WIDTH, height);
    fputs("<title>", f);
    text(f, pic->title ? pic->title : "garotor");
    fputs("</title>\n", f);
    fprintf(f, "<rect width=\"%d\" height=\"%d\" fill=\"#ffffff\"/>\n", WIDTH, height);
    fputs("<text x=\"12\" y=\"24\" font-size=\"15\">", f);
    text(f, pic->title ? pic->title : "garotor");
    fputs("</text>\n", f);

    if (pic->has_axis) {
        double x1, y1, x2, y2;
        point_xy(&c, axis_a, &x1, &y1);
        point_xy(&c, axis_b, &x2, &y2);
        fputs("<g stroke-width=\"1.5\" stroke-dasharray=\"8 5\">\n", f);
        line(f, x1, y1, x2, y2, screw_colour);
        fputs("</g>\n", f);
    }
    draw_paths(&c, pic);
    draw_keys(&c, pic);
    draw_legend(&c, pic, height);
    fputs("</svg>\n", f);
    return tio_out_finish(out);
}
