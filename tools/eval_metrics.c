/* tools/eval_metrics.c: the numbers of `garotor eval` (eval.h): statistics,
 * the Umeyama alignment by Horn's quaternion, rotation angles. */
#include "eval.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void ev_statistics(double *err, size_t n, ev_stats *out)
{
    double sum = 0, sse = 0;
    for (size_t i = 0; i < n; i++) sum += err[i], sse += err[i] * err[i];
    double mean = sum / (double)n, var = 0;
    for (size_t i = 0; i < n; i++) var += (err[i] - mean) * (err[i] - mean);
    qsort(err, n, sizeof *err, cmp_double);
    out->min = err[0];
    out->max = err[n - 1];
    out->median = n % 2 ? err[n / 2] : (err[n / 2 - 1] + err[n / 2]) / 2.0;
    out->mean = mean;
    out->sse = sse;
    out->rmse = sqrt(sse / (double)n);
    out->std = sqrt(var / (double)n);
}

double ev_angle(const ga_mat4 *m)
{
    const double *r = m->m;
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

int ev_align(const ga_mat4 *ref, const ga_mat4 *est, size_t n, int with_scale, ga_mat4 *T, double *s)
{
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
    double scale = 0;
    for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++) scale = fmax(scale, fabs(N[a][b]));
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
    if (!(d[top] - second > 1e-12 * scale) || (with_scale && !(varx > 0)))
        return -1;
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
    *T = R;
    *s = c;
    return 0;
}
