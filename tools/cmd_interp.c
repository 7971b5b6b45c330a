/* tools/cmd_interp.c: `garotor interp`, samples of a path through key poses.
 *
 * Reads keyframes (t, then a pose: 16 numbers with --format mat, 7 with
 * --format pose; KITTI's 12 with --format kitti), builds the path of --scheme
 * on --group (path.h), and writes t and the pose of each sample as
 * --output-format says. Everything is read and checked before anything is
 * written; the samples are then made once and written a chunk at a time,
 * never all held (interp_write.c). With --svg FILE it also draws the path
 * (svg.h); a failure then leaves neither the samples' file nor the picture.
 * The steps are in the files named in interp_cmd.h. */
#include "interp_cmd.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The path of --scheme on --group through the keys, in *work (allocated). */
static int build_path(const ic_opts *io, const ic_input *in, void **work, ga_path *path)
{
    size_t wbytes = ga_path_workspace_size(io->g, io->scheme, in->n);
    if (wbytes == 0) { /* the scheme is not defined on the group (path.h) */
        fprintf(stderr, "garotor interp: --scheme %s is not defined on --group %s\n",
                ga_scheme_name(io->scheme), io->g->name);
        return -1;
    }
    *work = malloc(wbytes);
    if (!*work)
        return ic_oom();
    int st = ga_path_init_mat4(io->g, io->scheme, in->n, in->times, in->keys, in->vel, *work, wbytes, path);
    if (st != GA_OK) {
        fprintf(stderr, "garotor interp: %s: cannot build the %s path: %s\n", in->in.name,
                ga_scheme_name(io->scheme), ga_status_string(st));
        return -1;
    }
    return 0;
}

/* The growth rule (path.h, docs/schemes.md "lihao2"): a warning, the
 * samples are written all the same (exit status 0). Its words are the
 * library's (ga_path_growth_describe), as garotor.Path's warning. */
static void warn_growth(const ic_opts *io, const ic_input *in, const ga_path *path)
{
    const tio_items *f = &in->in;
    ga_path_growth gr;
    ga_path_growth_words w;
    if (ga_path_measure_growth(path, &gr) != GA_OK || ga_path_growth_describe(path, &gr, &w) != GA_OK)
        return;
    fprintf(stderr,
            "garotor interp: warning: %s: the %s path's velocity grows past %g times the fastest chord on "
            "the segment t = %s to %s (lines %ld to %ld), up to %s times at t = %s; %s (docs/schemes.md)\n",
            f->name, ga_scheme_name(io->scheme), GA_PATH_GROWTH_MAX, f->first[w.a], f->first[w.b],
            f->item[w.a].line, f->item[w.b].line, w.ratio, f->first[gr.key], w.advice);
}

int cmd_interp(const cli_opts *o)
{
    ic_opts io;
    if (ic_options(o, &io))
        return 2;
    static ic_timebase tb; /* static: a tt_dec is large */
    memset(&tb, 0, sizeof tb);
    tb.ns = io.ns;
    ic_input in = {0};
    ic_sampler smp;
    ga_path path;
    void *work = NULL;
    int rc = 2;
    if ((o->at && ic_parse_at(o->at, &in)) || ic_read_keys(&io, &tb, &in) || ic_read_times(&io, &tb, &in) ||
        ic_plan(&io, &tb, &in, &smp) || ic_read_velocities(&io, &in) || build_path(&io, &in, &work, &path))
        goto done;
    warn_growth(&io, &in, &path);
    /* an algebra element as the tool writes it: a twist (6) on a rigid group,
       else its hat, a 4x4 with zero last row (16) */
    smp.path = &path;
    smp.dw = io.g->rigid ? 6 : 16;
    smp.pw = io.out_fmt == IC_OUT_MAT ? 17 : io.out_fmt == IC_OUT_KITTI ? 13 : 8; /* t and the pose */
    smp.width = smp.pw + (io.with_v + io.with_a + io.with_j) * smp.dw;
    if (ic_write(&io, &in, &smp) == 0)
        rc = 0;
done:
    free(work);
    ic_input_free(&in);
    return rc;
}
