/* interp/near_dup.c: keys closer in time than a minimum gap (path.h,
 * "Near-duplicate keys"): the default gap, 1% of the median spacing; the
 * runs of keys closer than it; and one key merged from such a run, at their
 * mean time with their mean pose. `garotor interp --min-gap, --dedup` and
 * garotor.Path's min_gap=, dedup= both call these.
 */
#include <math.h>

#include <garotor/path.h>
#include <garotor/rotor.h>
#include <garotor/trajectory.h>

ga_status ga_times_min_gap(size_t n, const double *times, double *scratch, double *median, double *gap)
{
    if (!times || !scratch || !median || !gap)
        return GA_ERR_ARG;
    if (n < 2) {
        *median = *gap = 0.0;
        return GA_OK;
    }
    for (size_t i = 1; i < n; i++) scratch[i - 1] = times[i] - times[i - 1];
    ga_traj_stats s; /* its median: the middle spacing, or the mean of the two middle ones */
    ga_status st = ga_traj_statistics(scratch, n - 1, &s);
    if (st != GA_OK)
        return st;
    if (!isfinite(s.median)) /* the mean of two middle spacings near DBL_MAX */
        return GA_ERR_DOMAIN;
    *median = s.median;
    *gap = GA_PATH_MIN_GAP_FRACTION * s.median;
    return GA_OK;
}

size_t ga_times_gap_run(size_t n, const double *times, double gap, size_t i)
{
    size_t j = i;
    if (!times || i >= n)
        return i;
    while (j + 1 < n && times[j + 1] - times[j] < gap) j++;
    return j;
}

ga_status ga_path_merge_keys(size_t m, const double *times, const ga_mat4 *keys, int ns, double *t,
                             ga_mat4 *key)
{
    if (!times || !keys || !t || !key || m == 0 || m > GA_PATH_MERGE_MAX)
        return GA_ERR_ARG;
    ga_rotor r[GA_PATH_MERGE_MAX], mean;
    double w[GA_PATH_MERGE_MAX], tm = 0.0;
    ga_status st = GA_OK;
    for (size_t k = 0; k < m; k++)
        if (!isfinite(times[k]))
            return GA_ERR_NOTFINITE;
    for (size_t k = 0; k < m && st == GA_OK; k++) {
        st = ga_rotor_from_mat4(keys[k], &r[k]);
        w[k] = 1.0;
        tm += times[k] / (double)m;
    }
    if (st == GA_OK)
        st = ga_rotor_mean(r, w, m, &mean);
    if (st != GA_OK)
        return st;
    /* the nearest whole number: x - floor(x) is exact, where floor(x + 0.5)
       rounds x + 0.5 first (up to an odd x + 1 between 2^52 and 2^53, and
       0.49999999999999994 up to 1) */
    double x = ns ? tm * 1e9 : tm, f = floor(x);
    if (ns)
        x = x - f >= 0.5 ? f + 1.0 : f;
    if (!isfinite(x))
        return GA_ERR_DOMAIN;
    *t = x;
    *key = ga_rotor_to_mat4(mean);
    return GA_OK;
}
