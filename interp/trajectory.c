/* interp/trajectory.c: two trajectories compared in evo's terms
 * (trajectory.h): TUM rows, association by time, the Umeyama alignment by
 * Horn's quaternion, APE, RPE and their statistics. `garotor eval` and the
 * Python module's evaluate call these.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include <garotor/mat4.h>
#include <garotor/rotor.h>
#include <garotor/trajectory.h>

static int finite_mat(const ga_mat4 *m)
{
    for (int k = 0; k < 16; k++)
        if (!isfinite(m->m[k]))
            return 0;
    return 1;
}

static int finite_mats(const ga_mat4 *m, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!finite_mat(&m[i]))
            return 0;
    return 1;
}

ga_status ga_traj_pose_from_tum(const double xyzq[7], int normalize, ga_mat4 *pose)
{
    if (!xyzq || !pose)
        return GA_ERR_ARG;
    for (int k = 0; k < 7; k++)
        if (!isfinite(xyzq[k]))
            return GA_ERR_NOTFINITE;
    ga_quat q = {xyzq[6], xyzq[3], xyzq[4], xyzq[5]};
    if (normalize) {
        ga_status st = ga_quat_normalize(q, GA_SE3_NORMALIZE_TOL, &q);
        if (st != GA_OK)
            return st;
    } else {
        double norm = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
        if (fabs(norm - 1.0) > 1e-9)
            return GA_ERR_NOTRIGID;
    }
    *pose = ga_rotor_to_mat4(ga_rotor_from_quat(q, (ga_vec3){xyzq[0], xyzq[1], xyzq[2]}));
    return GA_OK;
}

ga_status ga_traj_pose_to_tum(ga_mat4 pose, ga_quat *prev, double xyzq[7])
{
    if (!prev || !xyzq)
        return GA_ERR_ARG;
    ga_rotor r;
    if (ga_rotor_from_mat4(pose, &r) != GA_OK)
        r = ga_rotor_identity();
    ga_quat q = ga_rotor_to_quat(r);
    if (q.w * prev->w + q.x * prev->x + q.y * prev->y + q.z * prev->z < 0)
        q = (ga_quat){-q.w, -q.x, -q.y, -q.z};
    *prev = q;
    double v[7] = {pose.m[3], pose.m[7], pose.m[11], q.x, q.y, q.z, q.w};
    memcpy(xyzq, v, sizeof v);
    return GA_OK;
}

/* 0 when t[0..n-1] is finite and strictly increasing; else the status */
static ga_status check_times(const double *t, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(t[i]))
            return GA_ERR_NOTFINITE;
        if (i > 0 && !(t[i] > t[i - 1]))
            return GA_ERR_ARG;
    }
    return GA_OK;
}

/* The index of the time in t[0..n-1] (increasing) nearest x, the lower on a tie. */
static size_t nearest(const double *t, size_t n, double x)
{
    size_t lo = 0, hi = n; /* first index with t >= x */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (t[mid] < x)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == n)
        return n - 1;
    if (lo > 0 && fabs(t[lo - 1] - x) <= fabs(t[lo] - x))
        return lo - 1;
    return lo;
}

ga_status ga_traj_associate(const double *t_ref, size_t n_ref, const double *t_est, size_t n_est,
                            double max_diff, size_t *ref_index, size_t *est_index, size_t *n)
{
    if (!t_ref || !t_est || !ref_index || !est_index || !n || n_ref == 0 || n_est == 0 || isnan(max_diff) ||
        max_diff < 0)
        return GA_ERR_ARG;
    ga_status st = check_times(t_ref, n_ref);
    if (st == GA_OK)
        st = check_times(t_est, n_est);
    if (st != GA_OK)
        return st;
    /* evo: the estimate is the long one only when it has strictly more poses */
    int est_long = n_est > n_ref;
    const double *ts = est_long ? t_ref : t_est, *tl = est_long ? t_est : t_ref;
    size_t ns = est_long ? n_ref : n_est, nl = est_long ? n_est : n_ref;
    size_t *is = est_long ? ref_index : est_index, *il = est_long ? est_index : ref_index;
    size_t m = 0;
    for (size_t i = 0; i < ns; i++) {
        size_t j = nearest(tl, nl, ts[i]);
        if (fabs(tl[j] - ts[i]) <= max_diff)
            is[m] = i, il[m] = j, m++;
    }
    *n = m;
    return GA_OK;
}

double ga_traj_angle(ga_mat4 m)
{
    const double *r = m.m;
    double x = r[9] - r[6], y = r[2] - r[8], z = r[4] - r[1];
    return atan2(0.5 * sqrt(x * x + y * y + z * z), 0.5 * (r[0] + r[5] + r[10] - 1.0));
}

/* The eigenvalues (into d) and eigenvectors (columns of v) of the symmetric
 * 4x4 a, by cyclic Jacobi rotations (Golub and Van Loan, alg. 8.5.3). */
static void jacobi4(double a[4][4], double d[4], double v[4][4])
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) v[i][j] = i == j;
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = 0, norm = 0;
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                norm += a[i][j] * a[i][j];
                if (i != j)
                    off += a[i][j] * a[i][j];
            }
        if (off <= DBL_EPSILON * DBL_EPSILON * norm * 1e-4)
            break;
        for (int p = 0; p < 3; p++)
            for (int q = p + 1; q < 4; q++) {
                if (a[p][q] == 0)
                    continue;
                double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 4; k++) { /* a <- a J */
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 4; k++) { /* a <- J^T a */
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 4; k++) {
                    double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 4; i++) d[i] = a[i][i];
}

ga_status ga_traj_align(const ga_mat4 *ref, const ga_mat4 *est, size_t n, int with_scale, ga_mat4 *transform,
                        double *scale)
{
    if (!ref || !est || !transform || !scale || n == 0)
        return GA_ERR_ARG;
    if (!finite_mats(ref, n) || !finite_mats(est, n))
        return GA_ERR_NOTFINITE;
    if (n < 3)
        return GA_ERR_DOMAIN;
    double mx[3] = {0}, my[3] = {0};
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) mx[k] += est[i].m[4 * k + 3], my[k] += ref[i].m[4 * k + 3];
    for (int k = 0; k < 3; k++) mx[k] /= (double)n, my[k] /= (double)n;
    /* M[a][b] = (1/n) sum (x - mx)_a (y - my)_b, x the estimate, y the reference */
    double M[3][3] = {{0}}, varx = 0;
    for (size_t i = 0; i < n; i++) {
        double x[3], y[3];
        for (int k = 0; k < 3; k++) x[k] = est[i].m[4 * k + 3] - mx[k], y[k] = ref[i].m[4 * k + 3] - my[k];
        for (int a = 0; a < 3; a++) {
            varx += x[a] * x[a];
            for (int b = 0; b < 3; b++) M[a][b] += x[a] * y[b];
        }
    }
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) M[a][b] /= (double)n;
    varx /= (double)n;
    /* Horn's N (1987, eq. 4.A): its top eigenvector is the quaternion of the
       rotation taking x to y */
    double N[4][4] = {
        {M[0][0] + M[1][1] + M[2][2], M[1][2] - M[2][1], M[2][0] - M[0][2], M[0][1] - M[1][0]},
        {M[1][2] - M[2][1], M[0][0] - M[1][1] - M[2][2], M[0][1] + M[1][0], M[2][0] + M[0][2]},
        {M[2][0] - M[0][2], M[0][1] + M[1][0], -M[0][0] + M[1][1] - M[2][2], M[1][2] + M[2][1]},
        {M[0][1] - M[1][0], M[2][0] + M[0][2], M[1][2] + M[2][1], -M[0][0] - M[1][1] + M[2][2]}};
    double big = 0;
    for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++) big = fmax(big, fabs(N[a][b]));
    double d[4], V[4][4];
    jacobi4(N, d, V);
    int top = 0;
    for (int k = 1; k < 4; k++)
        if (d[k] > d[top])
            top = k;
    double second = -INFINITY;
    for (int k = 0; k < 4; k++)
        if (k != top)
            second = fmax(second, d[k]);
    if (!(d[top] - second > 1e-12 * big) || (with_scale && !(varx > 0)))
        return GA_ERR_DOMAIN;
    ga_quat q = {V[0][top], V[1][top], V[2][top], V[3][top]};
    double qn = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    q.w /= qn, q.x /= qn, q.y /= qn, q.z /= qn;
    ga_mat4 R = ga_rotor_to_mat4(ga_rotor_from_quat(q, (ga_vec3){0, 0, 0}));
    double c = 1.0;
    if (with_scale) { /* tr(R^T C), C = M^T the covariance of y against x */
        double tr = 0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) tr += R.m[4 * a + b] * M[b][a];
        c = tr / varx;
    }
    for (int a = 0; a < 3; a++) {
        double rx = R.m[4 * a] * mx[0] + R.m[4 * a + 1] * mx[1] + R.m[4 * a + 2] * mx[2];
        R.m[4 * a + 3] = my[a] - c * rx;
    }
    *transform = R;
    *scale = c;
    return GA_OK;
}

ga_status ga_traj_transform(ga_mat4 transform, double scale, const ga_mat4 *in, size_t n, ga_mat4 *out)
{
    if (!in || !out)
        return GA_ERR_ARG;
    if (!finite_mat(&transform) || !isfinite(scale) || !finite_mats(in, n))
        return GA_ERR_NOTFINITE;
    for (size_t k = 0; k < n; k++) {
        ga_mat4 e = in[k];
        for (int a = 0; a < 3; a++) e.m[4 * a + 3] *= scale;
        out[k] = ga_mat4_mul(transform, e);
    }
    return GA_OK;
}

ga_status ga_traj_ape(const ga_mat4 *ref, const ga_mat4 *est, size_t n, double angle_unit, double *trans_err,
                      double *rot_err)
{
    if (!ref || !est || !trans_err || !rot_err || n == 0 || !(angle_unit > 0))
        return GA_ERR_ARG;
    if (!isfinite(angle_unit) || !finite_mats(ref, n) || !finite_mats(est, n))
        return GA_ERR_NOTFINITE;
    /* E_i = est_i^-1 ref_i (evo: relative_se3(x_t, x_t*)) */
    for (size_t i = 0; i < n; i++) {
        double d2 = 0;
        for (int a = 0; a < 3; a++)
            d2 += (est[i].m[4 * a + 3] - ref[i].m[4 * a + 3]) * (est[i].m[4 * a + 3] - ref[i].m[4 * a + 3]);
        trans_err[i] = sqrt(d2);
        rot_err[i] = angle_unit * ga_traj_angle(ga_mat4_mul(ga_se3_inverse(est[i]), ref[i]));
    }
    return GA_OK;
}

size_t ga_traj_rpe_count(size_t n, size_t delta, int all_pairs)
{
    if (delta == 0 || delta >= n)
        return 0;
    return all_pairs ? n - delta : (n - delta - 1) / delta + 1;
}

ga_status ga_traj_rpe(const ga_mat4 *ref, const ga_mat4 *est, size_t n, size_t delta, int all_pairs,
                      double angle_unit, double *trans_err, double *rot_err)
{
    if (!ref || !est || !trans_err || !rot_err || ga_traj_rpe_count(n, delta, all_pairs) == 0 ||
        !(angle_unit > 0))
        return GA_ERR_ARG;
    if (!isfinite(angle_unit) || !finite_mats(ref, n) || !finite_mats(est, n))
        return GA_ERR_NOTFINITE;
    size_t m = 0;
    for (size_t i = 0; i + delta < n; i += all_pairs ? 1 : delta) {
        size_t j = i + delta;
        ga_mat4 q = ga_mat4_mul(ga_se3_inverse(ref[i]), ref[j]),
                p = ga_mat4_mul(ga_se3_inverse(est[i]), est[j]);
        ga_mat4 e = ga_mat4_mul(ga_se3_inverse(q), p);
        trans_err[m] = sqrt(e.m[3] * e.m[3] + e.m[7] * e.m[7] + e.m[11] * e.m[11]);
        rot_err[m] = angle_unit * ga_traj_angle(e);
        m++;
    }
    return GA_OK;
}

/* heapsort of a[0..n-1], increasing (no NaN) */
static void sift(double *a, size_t root, size_t n)
{
    for (;;) {
        size_t c = 2 * root + 1;
        if (c >= n)
            return;
        if (c + 1 < n && a[c + 1] > a[c])
            c++;
        if (!(a[c] > a[root]))
            return;
        double t = a[c];
        a[c] = a[root];
        a[root] = t;
        root = c;
    }
}

static void sort_doubles(double *a, size_t n)
{
    for (size_t i = n / 2; i-- > 0;) sift(a, i, n);
    for (size_t end = n; end-- > 1;) {
        double t = a[0];
        a[0] = a[end];
        a[end] = t;
        sift(a, 0, end);
    }
}

ga_status ga_traj_statistics(double *err, size_t n, ga_traj_stats *stats)
{
    if (!err || !stats || n == 0)
        return GA_ERR_ARG;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(err[i]))
            return GA_ERR_NOTFINITE;
    double sum = 0, sse = 0;
    for (size_t i = 0; i < n; i++) sum += err[i], sse += err[i] * err[i];
    double mean = sum / (double)n, var = 0;
    for (size_t i = 0; i < n; i++) var += (err[i] - mean) * (err[i] - mean);
    sort_doubles(err, n);
    ga_traj_stats s;
    s.min = err[0];
    s.max = err[n - 1];
    s.median = n % 2 ? err[n / 2] : (err[n / 2 - 1] + err[n / 2]) / 2.0;
    s.mean = mean;
    s.sse = sse;
    s.rmse = sqrt(sse / (double)n);
    s.std = sqrt(var / (double)n);
    *stats = s;
    return GA_OK;
}
