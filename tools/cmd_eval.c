/* tools/cmd_eval.c: `garotor eval` (docs/tool.md, "garotor eval"): read a
 * reference and an estimated trajectory (TUM: t x y z qx qy qz qw a line, as
 * `interp --format pose` reads keys), associate them by time as evo does
 * (evo.core.sync: each stamp of the shorter one to the nearest of the
 * other, kept within --max-diff), align (Umeyama: SE(3) or Sim(3)), and
 * report the absolute and relative pose errors, translation and rotation
 * parts, with evo's statistics (evo.core.metrics). Everything is read and
 * computed before the report is written; an error names the file and the
 * line and leaves nothing behind (exit status 2).
 */
#include "eval.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "columns.h"
#include "stamps.h"
#include "textio.h"
#include "timetext.h"

static const char eval_help[] =
    "usage: garotor eval --ref FILE --est FILE [OPTIONS]\n"
    "Compare an estimated trajectory with a reference, as evo_ape and evo_rpe do:\n"
    "each file has one pose a line, t x y z qx qy qz qw (TUM), t increasing.\n"
    "The poses are associated by time (each stamp of the file with fewer poses to\n"
    "the nearest of the other), optionally aligned, and the absolute (APE) and\n"
    "relative (RPE) pose errors reported: translation part (m) and rotation angle,\n"
    "each as max, mean, median, min, rmse, sse and std.\n"
    "  --ref FILE, --est FILE   the reference and the estimate\n"
    "  --max-diff S        largest time difference of an associated pair (default 0.01)\n"
    "  --offset S          added to the estimate's times before associating (default 0)\n"
    "  --align none|se3|sim3    Umeyama alignment of the estimate onto the reference:\n"
    "                      none (default), rotation and translation, or with scale\n"
    "  --delta N           RPE between pairs N poses apart (default 1)\n"
    "  --all-pairs         RPE over every pair (i, i+N), not consecutive ones\n"
    "  --angle deg|rad     the unit of rotation angles (default deg)\n"
    "  --normalize         accept quaternions up to 1e-3 from unit norm, normalised\n"
    "  --out FILE          the report (default standard output)\n"
    "  --time-unit s|ns    the stamps in seconds or whole nanoseconds (read exactly;\n"
    "                      --max-diff and --offset stay in seconds). Without it,\n"
    "                      whole numbers of 12 digits or more are an error (ms, us, ns?)\n"
    "  --stamps FILE       the stamps of a file of KITTI poses (12 numbers a line,\n"
    "                      the 3x4 [R t]): KITTI's times.txt, one a line\n"
    "  --columns LIST      both files' poses in any layout, as interp --columns reads\n"
    "                      them: the columns in order (t,x,y,z,qw,qx,qy,qz; - skips\n"
    "                      one), or ROLE=COLUMN pairs and header (names in line 1)\n"
    "  --ref-columns LIST, --est-columns LIST   one file's layout (over --columns)\n"
    "  --header            skip the first line of each file (a CSV header)\n"
    "  --max-line N        a line of more than N bytes is an error (default 1048576)\n";

typedef struct {
    const char *ref, *est, *out, *align_name, *angle_name, *max_line_text;
    const char *max_diff_text, *offset_text, *delta_text, *time_unit, *stamps;
    const char *columns, *ref_columns, *est_columns;
    double max_diff;
    long delta;
    int all_pairs, header, normalize, align, scale, degrees, ns;
    size_t max_line;
} ev_opts;

static int usage(const char *what, const char *arg)
{
    fprintf(stderr, "garotor eval: %s%s%s%s\n(garotor eval --help shows the options)\n", what,
            arg ? " '" : "", arg ? arg : "", arg ? "'" : "");
    return 2;
}

static int parse(int argc, char **argv, ev_opts *o)
{
    static const char *const names[] = {
        "--ref",         "--est",         "--out",       "--max-diff",  "--offset",   "--align",
        "--delta",       "--angle",       "--max-line",  "--time-unit", "--stamps",   "--columns",
        "--ref-columns", "--est-columns", "--all-pairs", "--header",    "--normalize"};
    enum { NVALUED = 14, NNAMES = 17 };
    const char **slot[NVALUED] = {&o->ref,           &o->est,        &o->out,        &o->max_diff_text,
                                  &o->offset_text,   &o->align_name, &o->delta_text, &o->angle_name,
                                  &o->max_line_text, &o->time_unit,  &o->stamps,     &o->columns,
                                  &o->ref_columns,   &o->est_columns};
    int *flag[3] = {&o->all_pairs, &o->header, &o->normalize};
    unsigned seen = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *eq = strchr(a, '=');
        size_t len = eq ? (size_t)(eq - a) : strlen(a);
        int k = 0;
        while (k < NNAMES && !(strlen(names[k]) == len && strncmp(a, names[k], len) == 0)) k++;
        if (k == NNAMES)
            return usage("unknown option", a);
        if (seen >> k & 1)
            return usage("option given twice", names[k]);
        seen |= 1u << k;
        if (k >= NVALUED) {
            if (eq)
                return usage("takes no value:", a);
            *flag[k - NVALUED] = 1;
            continue;
        }
        if (eq)
            *slot[k] = eq + 1;
        else if (i + 1 < argc)
            *slot[k] = argv[++i];
        else
            return usage("missing value for", a);
    }
    if (!o->ref || !o->est)
        return usage(!o->ref ? "--ref FILE is required (the reference trajectory)"
                             : "--est FILE is required (the estimated trajectory)",
                     NULL);
    char *end;
    o->max_diff = 0.01;
    if (o->max_diff_text) {
        o->max_diff = strtod(o->max_diff_text, &end);
        if (end == o->max_diff_text || *end || !(o->max_diff >= 0) || !isfinite(o->max_diff))
            return usage("--max-diff needs a number of seconds >= 0, not", o->max_diff_text);
    }
    if (o->offset_text) {
        double x = strtod(o->offset_text, &end);
        if (end == o->offset_text || *end || !isfinite(x))
            return usage("--offset needs a finite number of seconds, not", o->offset_text);
    }
    o->delta = 1;
    if (o->delta_text) {
        errno = 0;
        o->delta = strtol(o->delta_text, &end, 10);
        if (end == o->delta_text || *end || errno || o->delta < 1)
            return usage("--delta needs a whole number of poses >= 1, not", o->delta_text);
    }
    if (o->max_line_text) {
        errno = 0;
        unsigned long long m = strtoull(o->max_line_text, &end, 10);
        if (end == o->max_line_text || *end || errno || m < 1 || m > TIO_MAX_LINE_MAX ||
            o->max_line_text[0] == '-')
            return usage("--max-line needs a whole number of bytes >= 1, not", o->max_line_text);
        o->max_line = (size_t)m;
    }
    const char *al = o->align_name ? o->align_name : "none";
    if (strcmp(al, "none") == 0)
        o->align = 0;
    else if (strcmp(al, "se3") == 0)
        o->align = 1;
    else if (strcmp(al, "sim3") == 0)
        o->align = 1, o->scale = 1;
    else
        return usage("--align must be none, se3 or sim3, not", al);
    const char *an = o->angle_name ? o->angle_name : "deg";
    if (strcmp(an, "deg") != 0 && strcmp(an, "rad") != 0)
        return usage("--angle must be deg or rad, not", an);
    o->degrees = strcmp(an, "deg") == 0;
    const char *lists[3] = {o->columns, o->ref_columns, o->est_columns};
    for (int k = 0; k < 3; k++)
        if (lists[k] && col_check_list("eval", lists[k]))
            return 2;
    return st_time_unit("eval", o->time_unit, &o->ns) ? 2 : 0;
}

/* ---- reading ------------------------------------------------------------------ */

void ev_traj_free(ev_traj *tr)
{
    tio_free(&tr->in);
    free(tr->t);
    free(tr->m);
}

/* Pose i of a KITTI file: 12 numbers, the 3x4 [R t] row by row, a rigid
 * motion to 1e-9 (or within GA_SE3_NORMALIZE_TOL with normalize: projected
 * onto SE(3)). 0, or -1 after a message naming the line. */
static int kitti_pose(const tio_items *f, size_t i, int normalize, ga_mat4 *m)
{
    int c = f->item[i].count;
    if (c != 12)
        return tio_error(f, i, "expected 12 numbers (a KITTI pose: the 3x4 [R t] row by row), found %d%s", c,
                         c == 8 ? ": the first line of this file has 12: one file is TUM or KITTI, not both"
                                : "");
    memcpy(m->m, f->value + f->item[i].first, 12 * sizeof *m->m);
    m->m[12] = m->m[13] = m->m[14] = 0.0;
    m->m[15] = 1.0;
    ga_mat4 r;
    if (ga_se3_check(*m, 1e-9) == GA_OK)
        return 0;
    if (ga_se3_normalize(*m, GA_SE3_NORMALIZE_TOL, &r) != GA_OK)
        return tio_error(f, i, "columns 1-12 (a KITTI 3x4 [R t]): not a rigid motion%s",
                         normalize ? ", not even to 1e-3 (--normalize)"
                                   : " (to 1e-9; --normalize accepts up to 1e-3)");
    if (!normalize) {
        double off = 0.0;
        for (int k = 0; k < 16; k++) off = fmax(off, fabs(m->m[k] - r.m[k]));
        return tio_error(f, i,
                         "columns 1-12 (a KITTI 3x4 [R t]): not a rigid motion to 1e-9 (it is %.3g from the "
                         "nearest one); --normalize accepts up to 1e-3",
                         off);
    }
    *m = r;
    return 0;
}

int ev_traj_read(const char *path, const ev_read_opts *o, tt_dec *t0, int *have0, const tt_dec *shift,
                 ev_traj *tr, int *kitti)
{
    tio_read_opts ro = {o->header, 1, o->max_line};
    long col[COL_ROLES] = {0, 1, 2, 3, 4, 5, 6, 7}; /* each role's column, from 0 */
    if (o->columns ? col_read_poses(o->cmd ? o->cmd : "eval", path, o->columns, &ro, &tr->in, col)
                   : tio_read_first(path, &ro, &tr->in))
        return -1;
    char tcol[32], qcols[96];
    snprintf(tcol, sizeof tcol, "column %ld", col[0] + 1);
    if (col[5] == col[4] + 1 && col[6] == col[4] + 2 && col[7] == col[4] + 3)
        snprintf(qcols, sizeof qcols, "columns %ld-%ld", col[4] + 1, col[7] + 1);
    else
        snprintf(qcols, sizeof qcols, "columns %ld, %ld, %ld, %ld", col[4] + 1, col[5] + 1, col[6] + 1,
                 col[7] + 1);
    const tio_items *f = &tr->in;
    tr->n = f->n;
    if (f->n == 0) {
        fprintf(stderr, "garotor: %s: no poses\n", f->name);
        return -1;
    }
    int is_kitti = o->stamps && f->item[0].count == 12;
    if (kitti)
        *kitti = is_kitti;
    if (is_kitti && st_kitti_stamps(o->stamps, o->max_line, o->ns, o->guess_unit, &tr->in))
        return -1;
    tr->t = malloc(f->n * sizeof *tr->t);
    tr->m = malloc(f->n * sizeof *tr->m);
    if (!tr->t || !tr->m) {
        fprintf(stderr, "garotor: out of memory\n");
        return -1;
    }
    static tt_dec a, b, d;
    for (size_t i = 0; i < f->n; i++) {
        int c = f->item[i].count;
        if (!is_kitti && c != 8)
            return tio_error(f, i, "expected 8 numbers (t x y z qx qy qz qw), found %d%s", c,
                             c == 7    ? ": is t missing?"
                             : c == 17 ? ": a 4x4 matrix? eval reads TUM poses"
                             : c == 12 ? ": a KITTI pose (3x4, no t)? give its stamps with --stamps FILE"
                                       : "");
        if (i == 0 && o->guess_unit && st_guess_unit(f, 0))
            return -1;
        if (o->ns && st_whole_ns(f, i))
            return -1;
        const double *v = f->value + f->item[i].first;
        tt_parse(f->first[i], &a);
        if (!*have0) {
            *t0 = a;
            *have0 = 1;
        }
        tt_add(&a, shift, 0, &b);
        tt_add(&b, t0, 1, &d);
        tr->t[i] = tt_to_double(&d, o->ns ? -9 : 0);
        if (i > 0 && !(tr->t[i] > tr->t[i - 1]))
            return tio_error(f, i, "%s: times must increase strictly: %s after %s (%s)",
                             is_kitti ? "the stamp (--stamps)" : tcol, f->first[i], f->first[i - 1],
                             !(tr->t[i] < tr->t[i - 1])
                                 ? "a repeated stamp: keep one of the two lines"
                                 : "out of order: evo sorts by time, garotor reads the file as given: sort "
                                   "it by its first column, `sort -g -k1,1`");
        if (is_kitti) {
            if (kitti_pose(f, i, o->normalize, &tr->m[i]))
                return -1;
        } else if (ga_traj_pose_from_tum(v + 1, o->normalize, &tr->m[i]) != GA_OK) {
            double norm = sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
            return tio_error(f, i,
                             "%s (qx qy qz qw): the quaternion has norm %.17g, not 1 (to 1e-9; "
                             "--normalize accepts up to 1e-3)",
                             qcols, norm);
        }
    }
    return 0;
}

/* ---- the report --------------------------------------------------------------- */

static void put_stats(FILE *fp, const char *title, const char *align, double *err, size_t n)
{
    ga_traj_stats s;
    if (ga_traj_statistics(err, n, &s) != GA_OK)
        s = (ga_traj_stats){NAN, NAN, NAN, NAN, NAN, NAN, NAN};
    const char *name[7] = {"max", "mean", "median", "min", "rmse", "sse", "std"};
    double v[7] = {s.max, s.mean, s.median, s.min, s.rmse, s.sse, s.std};
    fprintf(fp, "\n%s\n%s\n\n", title, align);
    for (int k = 0; k < 7; k++) {
        char buf[GA_DOUBLE_TEXT_MAX];
        ga_double_format(v[k] == 0 ? 0.0 : v[k], buf);
        fprintf(fp, "%10s  %s\n", name[k], buf);
    }
}

static int run(const ev_opts *o, ev_traj *ref, ev_traj *est)
{
    ev_read_opts ro = {o->header, o->normalize, o->max_line, o->ns, !o->time_unit, o->stamps, NULL, "eval"};
    ev_read_opts re = ro;
    ro.columns = o->ref_columns ? o->ref_columns : o->columns;
    re.columns = o->est_columns ? o->est_columns : o->columns;
    static tt_dec t0, zero, off;
    int have0 = 0, kr = 0, ke = 0;
    tt_parse("0", &zero);
    tt_parse(o->offset_text ? o->offset_text : "0", &off);
    if (o->ns && off.n) /* --offset is in seconds: in nanoseconds, exactly */
        off.exp += 9;
    if (ev_traj_read(o->ref, &ro, &t0, &have0, &zero, ref, &kr) ||
        ev_traj_read(o->est, &re, &t0, &have0, &off, est, &ke))
        return 2;
    if (o->stamps && !kr && !ke) {
        fprintf(stderr,
                "garotor eval: --stamps gives KITTI poses (12 numbers a line) their stamps, but %s and %s "
                "are TUM (t and 7 numbers): drop --stamps\n",
                ref->in.name, est->in.name);
        return 2;
    }
    size_t cap = ref->n < est->n ? ref->n : est->n, n = 0;
    size_t *ir = malloc(cap * sizeof *ir), *ie = malloc(cap * sizeof *ie);
    ga_mat4 *R = malloc(cap * sizeof *R), *E = malloc(cap * sizeof *E);
    double *err = malloc(cap * sizeof *err), *err2 = malloc(cap * sizeof *err2);
    int rc = 2;
    if (!ir || !ie || !R || !E || !err || !err2) {
        fprintf(stderr, "garotor eval: out of memory\n");
        goto done;
    }
    if (ga_traj_associate(ref->t, ref->n, est->t, est->n, o->max_diff, ir, ie, &n) != GA_OK)
        goto done; /* not reached: the reader checked the times */
    if (n == 0) {
        /* evo: the estimate is the long one only when it has strictly more poses */
        const ev_traj *sh = est->n > ref->n ? ref : est, *lg = est->n > ref->n ? est : ref;
        fprintf(stderr,
                "garotor eval: no pose of %s is within --max-diff %s s of a pose of %s (--offset %s)\n",
                sh->in.name, o->max_diff_text ? o->max_diff_text : "0.01", lg->in.name,
                o->offset_text ? o->offset_text : "0");
        goto done;
    }
    for (size_t k = 0; k < n; k++) R[k] = ref->m[ir[k]], E[k] = est->m[ie[k]];
    double scale = 1.0;
    const char *align = "(not aligned)";
    if (o->align) {
        ga_mat4 T;
        if (ga_traj_align(R, E, n, o->scale, &T, &scale) != GA_OK ||
            ga_traj_transform(T, scale, E, n, E) != GA_OK) {
            fprintf(stderr,
                    "garotor eval: --align %s: the %zu associated positions do not fix an alignment "
                    "(fewer than 3, or on one line)\n",
                    o->align_name, n);
            goto done;
        }
        align = o->scale ? "(with Sim(3) Umeyama alignment)" : "(with SE(3) Umeyama alignment)";
    }
    size_t npairs = ga_traj_rpe_count(n, (size_t)o->delta, o->all_pairs);
    if (npairs == 0) {
        fprintf(stderr, "garotor eval: --delta %ld leaves no pair among the %zu associated poses\n", o->delta,
                n);
        goto done;
    }
    tio_out out = TIO_OUT_NONE;
    if (tio_out_open(&out, o->out))
        goto done;
    FILE *fp = out.fp;
    fprintf(fp, "compared %zu pose pairs (reference %zu poses, estimate %zu; max time difference %s s)\n", n,
            ref->n, est->n, o->max_diff_text ? o->max_diff_text : "0.01");
    if (o->scale) {
        char buf[GA_DOUBLE_TEXT_MAX];
        ga_double_format(scale, buf);
        fprintf(fp, "Sim(3) scale correction %s\n", buf);
    }
    const char *unit = o->degrees ? "deg" : "rad";
    double k = o->degrees ? 180.0 / 3.14159265358979323846 : 1.0;
    char title[160], rpe_for[96];
    /* APE: E_i = est_i^-1 ref_i (evo: relative_se3(x_t, x_t*)) */
    if (ga_traj_ape(R, E, n, k, err, err2) != GA_OK) {
        tio_out_discard(&out);
        fprintf(stderr, "garotor eval: the poses are not finite after --align\n");
        goto done;
    }
    put_stats(fp, "APE w.r.t. translation part (m)", align, err, n);
    snprintf(title, sizeof title, "APE w.r.t. rotation angle (%s)", unit);
    put_stats(fp, title, align, err2, n);
    /* RPE: E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j), Q the reference, P the estimate */
    if (ga_traj_rpe(R, E, n, (size_t)o->delta, o->all_pairs, k, err, err2) != GA_OK) {
        tio_out_discard(&out);
        fprintf(stderr, "garotor eval: the poses are not finite after --align\n");
        goto done;
    }
    snprintf(rpe_for, sizeof rpe_for, "for delta = %ld (frames) using %s pairs", o->delta,
             o->all_pairs ? "all" : "consecutive");
    snprintf(title, sizeof title, "RPE w.r.t. translation part (m)\n%s", rpe_for);
    put_stats(fp, title, align, err, npairs);
    snprintf(title, sizeof title, "RPE w.r.t. rotation angle (%s)\n%s", unit, rpe_for);
    put_stats(fp, title, align, err2, npairs);
    rc = tio_out_close(&out, 1) ? 2 : 0;
done:
    free(ir);
    free(ie);
    free(R);
    free(E);
    free(err);
    free(err2);
    return rc;
}

int cmd_eval_main(int argc, char **argv)
{
    for (int i = 0; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(eval_help, stdout);
            return 0;
        }
    ev_opts o;
    memset(&o, 0, sizeof o);
    if (parse(argc, argv, &o))
        return 2;
    ev_traj ref, est;
    memset(&ref, 0, sizeof ref);
    memset(&est, 0, sizeof est);
    int rc = run(&o, &ref, &est);
    ev_traj_free(&ref);
    ev_traj_free(&est);
    return rc;
}
