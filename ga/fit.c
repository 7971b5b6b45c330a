/* garotor/fit.c: least-squares spheres, planes, circles and lines through n
 * points, by the linear method of the conformal model (Dorst, "Total least
 * squares fitting of k-spheres in n-D Euclidean space using an
 * (n+2)-D isometric representation", J. Math. Imaging Vis. 50, 2014;
 * Hildenbrand, "Foundations of Geometric Algebra Computing", 2013).
 *
 * A dual sphere or plane s = m + a n + b nbar (m Euclidean) has
 * F(x).s = b |x|^2 + m.x - a, zero on the object, and s^2 = |m|^2 + 4 a b
 * (r^2 times (2b)^2 for a sphere, |m|^2 for a plane). In the coordinates
 * t = (b, m1, m2, m3, a), F(x_i).s = z_i.t with z_i = (|x_i|^2, x_i, -1), and
 * s^2 = t^T G t with G the metric of those coordinates. The fit minimises
 *
 *     sum_i (F(x_i).s)^2 = |Z t|^2     subject to  s^2 = t^T G t = 1:
 *
 * the 5x5 generalised eigenproblem Z^T Z t = mu G t (Dorst's matrix
 * sum_i P_i P_i^T with the metric), whose smallest mu >= 0 gives the sphere
 * (Pratt's normalisation, 1987). It is solved without forming Z^T Z: Z's
 * rows are rotated into a triangular R (Givens, one point at a time, no
 * storage), R = U S V^T by one-sided Jacobi, and with t = V S^-1 y the
 * problem becomes: maximise y^T K y / |y|^2, K = S^-1 V^T G V S^-1
 * symmetric, whose largest eigenvalues (Jacobi) give the best spheres. A
 * circle is the meet of the two best (s1 ^ s2: the pencil of spheres through
 * it, its plane among them); a plane and a line are the same problem with
 * b = 0 (flats), which is total least squares (principal components).
 *
 * Everything is computed about the centroid o of the points in units of
 * their RMS distance lambda from it, and moved back: so the embedding adds
 * no cancellation of |x|^2 beside 1 however far the points are.
 */
#include <garotor/fit.h>

#include <float.h>
#include <math.h>

#define U DBL_EPSILON

/* ---- small dense linear algebra (5 x 5 at most) ---------------------------------- */

enum { N5 = 5 };

/* r := rotate the row z into the upper-triangular r (k columns) */
static void qr_add_row(double r[N5][N5], double z[N5], int k)
{
    for (int i = 0; i < k; i++) {
        if (z[i] == 0.0)
            continue;
        double h = hypot(r[i][i], z[i]), c = r[i][i] / h, s = z[i] / h;
        for (int j = i; j < k; j++) {
            double a = r[i][j], b = z[j];
            r[i][j] = c * a + s * b;
            z[j] = c * b - s * a;
        }
        z[i] = 0.0;
    }
}

/* One-sided Jacobi SVD of the k x k matrix a: a = U S V^T, s[j] the norm of
   column j of a V (a is overwritten by U S), v the right singular vectors
   in its columns. */
static void svd_jacobi(double a[N5][N5], int k, double s[N5], double v[N5][N5])
{
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++) v[i][j] = i == j;
    for (int sweep = 0; sweep < 60; sweep++) {
        int rotated = 0;
        for (int p = 0; p < k - 1; p++)
            for (int q = p + 1; q < k; q++) {
                double alpha = 0, beta = 0, gamma = 0;
                for (int i = 0; i < k; i++) {
                    alpha += a[i][p] * a[i][p];
                    beta += a[i][q] * a[i][q];
                    gamma += a[i][p] * a[i][q];
                }
                if (gamma == 0.0 || fabs(gamma) <= U * sqrt(alpha * beta))
                    continue;
                rotated = 1;
                double zeta = (beta - alpha) / (2 * gamma);
                double t = copysign(1.0, zeta) / (fabs(zeta) + sqrt(1 + zeta * zeta));
                double c = 1 / sqrt(1 + t * t), sn = c * t;
                for (int i = 0; i < k; i++) {
                    double x = a[i][p], y = a[i][q];
                    a[i][p] = c * x - sn * y;
                    a[i][q] = sn * x + c * y;
                    x = v[i][p], y = v[i][q];
                    v[i][p] = c * x - sn * y;
                    v[i][q] = sn * x + c * y;
                }
            }
        if (!rotated)
            break;
    }
    for (int j = 0; j < k; j++) {
        double t = 0;
        for (int i = 0; i < k; i++) t += a[i][j] * a[i][j];
        s[j] = sqrt(t);
    }
}

/* Jacobi eigenvalues of the symmetric k x k matrix a (destroyed): ev, and
   the eigenvectors in the columns of v */
static void eig_jacobi(double a[N5][N5], int k, double ev[N5], double v[N5][N5])
{
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++) v[i][j] = i == j;
    for (int sweep = 0; sweep < 60; sweep++) {
        double off = 0, diag = 0;
        for (int p = 0; p < k; p++) {
            diag += a[p][p] * a[p][p];
            for (int q = p + 1; q < k; q++) off += a[p][q] * a[p][q];
        }
        if (off <= U * U * diag * 1e-4 || off == 0.0)
            break;
        for (int p = 0; p < k - 1; p++)
            for (int q = p + 1; q < k; q++) {
                if (a[p][q] == 0.0)
                    continue;
                double zeta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                double t = copysign(1.0, zeta) / (fabs(zeta) + sqrt(1 + zeta * zeta));
                double c = 1 / sqrt(1 + t * t), s = c * t;
                for (int i = 0; i < k; i++) { /* a := a J (columns p, q) */
                    double x = a[i][p], y = a[i][q];
                    a[i][p] = c * x - s * y;
                    a[i][q] = s * x + c * y;
                }
                for (int i = 0; i < k; i++) { /* a := J^T a (rows p, q) */
                    double x = a[p][i], y = a[q][i];
                    a[p][i] = c * x - s * y;
                    a[q][i] = s * x + c * y;
                }
                for (int i = 0; i < k; i++) {
                    double x = v[i][p], y = v[i][q];
                    v[i][p] = c * x - s * y;
                    v[i][q] = s * x + c * y;
                }
            }
    }
    for (int i = 0; i < k; i++) ev[i] = a[i][i];
}

/* ---- the points about their centroid ----------------------------------------------- */

typedef struct {
    ga_vec3 o;     /* the centroid */
    double lambda; /* the RMS distance from it */
} frame;

static int check_points(const ga_vec3 *pts, size_t n, size_t least)
{
    if (n < least)
        return GA_ERR_ARG;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(pts[i].x) || !isfinite(pts[i].y) || !isfinite(pts[i].z))
            return GA_ERR_NOTFINITE;
    return GA_OK;
}

/* the centroid (with a second pass for the mean's rounding) and the RMS
   distance; GA_ERR_DOMAIN when all points coincide or a sum overflows */
static int make_frame(const ga_vec3 *pts, size_t n, frame *f)
{
    double sx = 0, sy = 0, sz = 0;
    for (size_t i = 0; i < n; i++) sx += pts[i].x, sy += pts[i].y, sz += pts[i].z;
    ga_vec3 o = {sx / (double)n, sy / (double)n, sz / (double)n};
    double cx = 0, cy = 0, cz = 0, ss = 0;
    for (size_t i = 0; i < n; i++) cx += pts[i].x - o.x, cy += pts[i].y - o.y, cz += pts[i].z - o.z;
    o.x += cx / (double)n, o.y += cy / (double)n, o.z += cz / (double)n;
    double big = 0;
    for (size_t i = 0; i < n; i++)
        big = fmax(big, fmax(fabs(pts[i].x - o.x), fmax(fabs(pts[i].y - o.y), fabs(pts[i].z - o.z))));
    if (!(big > 0.0) || !isfinite(big) || !isfinite(o.x + o.y + o.z))
        return GA_ERR_DOMAIN;
    for (size_t i = 0; i < n; i++) {
        double dx = (pts[i].x - o.x) / big, dy = (pts[i].y - o.y) / big, dz = (pts[i].z - o.z) / big;
        ss += dx * dx + dy * dy + dz * dz;
    }
    f->o = o;
    f->lambda = big * sqrt(ss / (double)n);
    return GA_OK;
}

static ga_vec3 local(const frame *f, ga_vec3 x)
{
    return (ga_vec3){(x.x - f->o.x) / f->lambda, (x.y - f->o.y) / f->lambda, (x.z - f->o.z) / f->lambda};
}

/* ---- the eigenproblem ------------------------------------------------------------ */

/* The metric of t = (b, m1, m2, m3, a): s^2 = m.m + 4 a b */
static const double G5[N5][N5] = {
    {0, 0, 0, 0, 2}, {0, 1, 0, 0, 0}, {0, 0, 1, 0, 0}, {0, 0, 0, 1, 0}, {2, 0, 0, 0, 0}};

/* The rounds: the k best dual spheres t[0..k-1] (k = 1 or 2), best first,
   each with t^T G t = 1; GA_ERR_DOMAIN where the (k+1)-th is as good to
   rounding (no unique answer: points on a circle for a sphere, or on a line
   for a circle) */
static int best_rounds(const ga_vec3 *pts, size_t n, const frame *f, int k, double t[2][N5])
{
    double r[N5][N5] = {{0}};
    for (size_t i = 0; i < n; i++) {
        ga_vec3 x = local(f, pts[i]);
        double z[N5] = {x.x * x.x + x.y * x.y + x.z * x.z, x.x, x.y, x.z, -1.0};
        qr_add_row(r, z, N5);
    }
    double s[N5], v[N5][N5];
    svd_jacobi(r, N5, s, v);
    double smax = 0;
    for (int j = 0; j < N5; j++) smax = fmax(smax, s[j]);
    /* columns with a singular value that is rounding (points exactly on the
       object) are taken at u smax: their direction is what matters */
    double floor_s = U * smax;
    double K[N5][N5], w[N5], y[N5][N5];
    for (int p = 0; p < N5; p++)
        for (int q = 0; q < N5; q++) {
            double g = 0;
            for (int i = 0; i < N5; i++)
                for (int j = 0; j < N5; j++) g += v[i][p] * G5[i][j] * v[j][q];
            K[p][q] = g / (fmax(s[p], floor_s) * fmax(s[q], floor_s));
        }
    eig_jacobi(K, N5, w, y);
    /* the k + 1 largest eigenvalues, in order */
    int idx[N5] = {0, 1, 2, 3, 4};
    for (int i = 0; i < N5; i++)
        for (int j = i + 1; j < N5; j++)
            if (w[idx[j]] > w[idx[i]]) {
                int tmp = idx[i];
                idx[i] = idx[j];
                idx[j] = tmp;
            }
    /* mu = 1 / kappa: the sum of squared algebraic distances; the (k+1)-th as
       small as the k-th to rounding means no unique answer */
    double kap = w[idx[k - 1]], next = w[idx[k]];
    if (!(kap > 0.0) || next >= kap * (1 - 64 * U) ||
        (next > 0.0 && 1.0 / next <= (64 * U * smax) * (64 * U * smax)))
        return GA_ERR_DOMAIN;
    for (int m = 0; m < k; m++) {
        double tt[N5];
        for (int i = 0; i < N5; i++) {
            tt[i] = 0;
            for (int j = 0; j < N5; j++) tt[i] += v[i][j] * y[j][idx[m]] / fmax(s[j], floor_s);
        }
        double g = 0;
        for (int i = 0; i < N5; i++)
            for (int j = 0; j < N5; j++) g += tt[i] * G5[i][j] * tt[j];
        if (!(g > 0.0))
            return GA_ERR_DOMAIN;
        for (int i = 0; i < N5; i++) t[m][i] = tt[i] / sqrt(g);
    }
    return GA_OK;
}

/* The flats: the principal directions of the points about their centroid,
   e[0] the one of the largest spread; sv their singular values */
static void principal(const ga_vec3 *pts, size_t n, const frame *f, ga_vec3 e[3], double sv[3])
{
    double r[N5][N5] = {{0}};
    for (size_t i = 0; i < n; i++) {
        ga_vec3 x = local(f, pts[i]);
        double z[N5] = {x.x, x.y, x.z, 0, 0};
        qr_add_row(r, z, 3);
    }
    double s[N5], v[N5][N5];
    svd_jacobi(r, 3, s, v);
    int idx[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (s[idx[j]] > s[idx[i]]) {
                int tmp = idx[i];
                idx[i] = idx[j];
                idx[j] = tmp;
            }
    for (int m = 0; m < 3; m++) {
        e[m] = (ga_vec3){v[0][idx[m]], v[1][idx[m]], v[2][idx[m]]};
        sv[m] = s[idx[m]];
    }
}

static double dot3(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ga_vec3 axpy(double a, ga_vec3 x, ga_vec3 y)
{
    return (ga_vec3){a * x.x + y.x, a * x.y + y.y, a * x.z + y.z};
}
static ga_vec3 unit(ga_vec3 x)
{
    double h = sqrt(dot3(x, x));
    return (ga_vec3){x.x / h, x.y / h, x.z / h};
}

/* x / |x|, its largest component positive: a sign that does not depend on
   the Jacobi rotations that found x */
static ga_vec3 signed_unit(ga_vec3 x)
{
    ga_vec3 m = unit(x);
    double big = m.x;
    if (fabs(m.y) > fabs(big))
        big = m.y;
    if (fabs(m.z) > fabs(big))
        big = m.z;
    return big < 0 ? (ga_vec3){-m.x, -m.y, -m.z} : m;
}
static int finite3(ga_vec3 x) { return isfinite(x.x) && isfinite(x.y) && isfinite(x.z); }

/* ---- the fits ------------------------------------------------------------------------ */

ga_status ga_fit_sphere(const ga_vec3 *pts, size_t n, ga_vec3 *centre, double *radius)
{
    if (!pts || !centre || !radius)
        return GA_ERR_ARG;
    ga_status st = check_points(pts, n, 4);
    frame f;
    double t[2][N5];
    if (st != GA_OK || (st = make_frame(pts, n, &f)) != GA_OK ||
        (st = best_rounds(pts, n, &f, 1, t)) != GA_OK)
        return st;
    /* b |x|^2 + m.x - a = b (|x - c|^2 - r^2): c = -m / (2b), r = 1 / (2 |b|)
       (s^2 = 1); a plane to rounding (b below u |t|) has no centre */
    double b = t[0][0], tn = 0;
    for (int i = 0; i < N5; i++) tn = fmax(tn, fabs(t[0][i]));
    if (!(fabs(b) > 64 * U * tn))
        return GA_ERR_DOMAIN;
    ga_vec3 m = {t[0][1], t[0][2], t[0][3]};
    ga_vec3 c = axpy(-f.lambda / (2 * b), m, f.o);
    double r = f.lambda / (2 * fabs(b));
    if (!finite3(c) || !isfinite(r))
        return GA_ERR_DOMAIN;
    *centre = c;
    *radius = r;
    return GA_OK;
}

/* The checks of at least `least` points, the frame about their centroid and
   the principal directions e with their spreads sv (largest first): what the
   plane's and the line's fits share. */
static ga_status principal_frame(const ga_vec3 *pts, size_t n, size_t least, frame *f, ga_vec3 e[3],
                                 double sv[3])
{
    ga_status st = check_points(pts, n, least);
    if (st != GA_OK || (st = make_frame(pts, n, f)) != GA_OK)
        return st;
    principal(pts, n, f, e, sv);
    return GA_OK;
}

ga_status ga_fit_plane(const ga_vec3 *pts, size_t n, ga_vec3 *normal, double *distance)
{
    if (!pts || !normal || !distance)
        return GA_ERR_ARG;
    frame f;
    ga_vec3 e[3];
    double sv[3];
    ga_status st = principal_frame(pts, n, 3, &f, e, sv);
    if (st != GA_OK)
        return st;
    if (!(sv[1] > 64 * U * sv[0]))
        return GA_ERR_DOMAIN; /* collinear: every plane through the line fits */
    ga_vec3 m = signed_unit(e[2]);
    *normal = m;
    *distance = dot3(m, f.o);
    return GA_OK;
}

ga_status ga_fit_line(const ga_vec3 *pts, size_t n, ga_vec3 *direction, ga_vec3 *point)
{
    if (!pts || !direction || !point)
        return GA_ERR_ARG;
    frame f;
    ga_vec3 e[3];
    double sv[3];
    ga_status st = principal_frame(pts, n, 2, &f, e, sv);
    if (st != GA_OK)
        return st;
    if (!(sv[0] > sv[1] * (1 + 64 * U)))
        return GA_ERR_DOMAIN; /* no direction of largest spread */
    ga_vec3 u = signed_unit(e[0]);
    *direction = u;
    *point = axpy(-dot3(u, f.o), u, f.o);
    return GA_OK;
}

ga_status ga_fit_circle(const ga_vec3 *pts, size_t n, ga_vec3 *centre, double *radius, ga_vec3 *normal)
{
    if (!pts || !centre || !radius || !normal)
        return GA_ERR_ARG;
    ga_status st = check_points(pts, n, 3);
    frame f;
    double t[2][N5];
    if (st != GA_OK || (st = make_frame(pts, n, &f)) != GA_OK ||
        (st = best_rounds(pts, n, &f, 2, t)) != GA_OK)
        return st;
    /* the pencil s1 ^ s2: its plane is the member with b = 0, its centre
       that of any sphere of it moved into the plane */
    double b1 = t[0][0], b2 = t[1][0];
    double p[N5];
    for (int i = 0; i < N5; i++) p[i] = b2 * t[0][i] - b1 * t[1][i];
    ga_vec3 m = {p[1], p[2], p[3]};
    double mm = sqrt(dot3(m, m));
    if (!(mm > 0.0))
        return GA_ERR_DOMAIN;
    ga_vec3 u = {m.x / mm, m.y / mm, m.z / mm};
    double d = p[4] / mm; /* the plane u.x = d */
    const double *sp = fabs(b1) >= fabs(b2) ? t[0] : t[1];
    double b = sp[0], tn = 0;
    for (int i = 0; i < N5; i++) tn = fmax(tn, fabs(sp[i]));
    if (!(fabs(b) > 64 * U * tn))
        return GA_ERR_DOMAIN; /* both are planes to rounding: the points are on a line */
    ga_vec3 cs = {-sp[1] / (2 * b), -sp[2] / (2 * b), -sp[3] / (2 * b)};
    double rs2 = 1.0 / (4 * b * b); /* s^2 = 1 */
    double h = dot3(u, cs) - d;
    double r2 = rs2 - h * h;
    if (!(r2 > 0.0))
        return GA_ERR_DOMAIN; /* the best pencil holds no real circle */
    ga_vec3 c = axpy(-h, u, cs);
    double big = u.x;
    if (fabs(u.y) > fabs(big))
        big = u.y;
    if (fabs(u.z) > fabs(big))
        big = u.z;
    if (big < 0)
        u = (ga_vec3){-u.x, -u.y, -u.z};
    ga_vec3 cw = axpy(f.lambda, c, f.o);
    double r = f.lambda * sqrt(r2);
    if (!finite3(cw) || !isfinite(r))
        return GA_ERR_DOMAIN;
    *centre = cw;
    *radius = r;
    *normal = u;
    return GA_OK;
}
