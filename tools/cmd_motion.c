/* tools/cmd_motion.c: `garotor exp` and `garotor log`, one motion a line.
 *
 * Both go through the group interface (group.h), so `--group cga` computes
 * with rotors (Wareham-Lasenby), `--group matrix` with Eberly's SE(3) closed
 * forms and `--group affine` with the general matrix exp and log. */
#include "cli.h"
#include "textio.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <garotor/garotor.h>

const ga_group *cli_group(const char *cmd, const cli_opts *o)
{
    const char *name = o->group ? o->group : "cga";
    const ga_group *g = ga_group_by_name(name);
    if (!g)
        fprintf(stderr, "garotor %s: --group must be cga, matrix or affine, not '%s'\n", cmd, name);
    return g;
}

int cli_check_motion(const ga_group *g, ga_mat4 m, const tio_items *in, size_t i)
{
    const double *a = m.m;
    double last = fmax(fmax(fabs(a[12]), fabs(a[13])), fmax(fabs(a[14]), fabs(a[15] - 1.0)));
    if (last > 1e-9)
        return tio_error(in, i, "not a homogeneous matrix: the last row is not 0 0 0 1");
    double det = a[0] * (a[5] * a[10] - a[6] * a[9]) - a[1] * (a[4] * a[10] - a[6] * a[8]) +
                 a[2] * (a[4] * a[9] - a[5] * a[8]);
    if (!g->rigid) {
        if (!(det > 0.0))
            return tio_error(in, i, "the determinant is %g; the affine group needs it positive", det);
        return 0;
    }
    double off = 0.0; /* max |R^T R - I| */
    for (int r = 0; r < 3; r++)
        for (int s = 0; s < 3; s++) {
            double d = a[r] * a[s] + a[4 + r] * a[4 + s] + a[8 + r] * a[8 + s];
            off = fmax(off, fabs(d - (r == s)));
        }
    if (off > 1e-9)
        return tio_error(in, i,
                         "not a rigid motion: the rotation part is not orthonormal "
                         "(max |R^T R - I| = %.3g > 1e-9)",
                         off);
    if (!(det > 0.0))
        return tio_error(in, i, "not a rigid motion: the rotation part is a reflection (det < 0)");
    return 0;
}

/* An algebra element as the tool writes it: a twist (6 numbers) on a rigid
 * group (cga, matrix), else its hat, a 4x4 matrix with zero last row (16
 * numbers; affine). */
static int algebra_count(const ga_group *g) { return g->rigid ? 6 : 16; }

static int run(const char *cmd, const cli_opts *o, int is_exp)
{
    const ga_group *g = cli_group(cmd, o);
    if (!g)
        return 2;
    tio_items in;
    tio_read_opts ro = cli_input(o);
    if (tio_read(o->in, &ro, &in))
        return 2;
    int want = is_exp ? algebra_count(g) : 16;
    for (size_t i = 0; i < in.n; i++)
        if (in.item[i].count != want) {
            /* a matrix given to exp, a twist given to log: the other command */
            int m = in.item[i].count;
            const char *hint = is_exp && want == 6 && m == 16 ? ": is this a matrix? garotor log reads those"
                             : !is_exp && m == 6              ? ": is this a twist? garotor exp reads those"
                                                              : "";
            tio_error(&in, i, "expected %d numbers (%s), found %d%s", want,
                      is_exp ? (want == 6 ? "a twist" : "a 4x4 matrix with last row zero") : "a 4x4 matrix",
                      m, hint);
            tio_free(&in);
            return 2;
        }
    /* compute everything first: an error on line 9 leaves no partial output */
    int nout = is_exp ? 16 : algebra_count(g);
    double *res = malloc((in.n ? in.n : 1) * (size_t)nout * sizeof *res);
    int ok = res != NULL;
    if (!ok)
        fprintf(stderr, "garotor %s: out of memory\n", cmd);
    double elem[GA_GROUP_MAX_ELEM];
    for (size_t i = 0; i < in.n && ok; i++) {
        const double *v = in.value + in.item[i].first;
        double *r = res + i * (size_t)nout;
        int st;
        if (is_exp) {
            double x[GA_GROUP_MAX_DIM];
            if (g->rigid) {
                memcpy(x, v, 6 * sizeof *x);
            } else {
                ga_mat4 a;
                memcpy(a.m, v, sizeof a.m);
                if (g->vee(a, x) != GA_OK) {
                    ok = !tio_error(&in, i, "the last row of an affine generator must be 0 0 0 0");
                    break;
                }
            }
            st = g->exp(x, elem);
            if (st == GA_OK) {
                ga_mat4 m = g->to_mat4(elem);
                memcpy(r, m.m, sizeof m.m);
            }
        } else {
            ga_mat4 m;
            memcpy(m.m, v, sizeof m.m);
            if (cli_check_motion(g, m, &in, i)) {
                ok = 0;
                break;
            }
            double x[GA_GROUP_MAX_DIM];
            st = g->from_mat4(m, elem);
            if (st == GA_OK)
                st = g->log(elem, x);
            if (st == GA_OK && g->rigid)
                memcpy(r, x, 6 * sizeof *x);
            else if (st == GA_OK)
                memcpy(r, g->hat(x).m, 16 * sizeof *x);
        }
        if (st != GA_OK)
            ok = !tio_error(&in, i, "%s", ga_status_string(st));
    }
    ok = ok && tio_write_rows(o->out, res, in.n, nout) == 0;
    free(res);
    tio_free(&in);
    return ok ? 0 : 2;
}

int cmd_exp(const cli_opts *o) { return run("exp", o, 1); }
int cmd_log(const cli_opts *o) { return run("log", o, 0); }
