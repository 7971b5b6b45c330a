/* python/path_times.c: garotor.Path's times (path.h, docs/python.md,
 * "Times"). A time is read as the exact decimal it was given as: an integer
 * exactly, a float as its shortest decimal (ga_double_shortest, the text
 * the tool reads when the float is written with repr). The path is built on
 * each key's time minus the first key's, the difference exact and rounded
 * once to a double in seconds (x 1e-9 with time_unit='ns'), as `garotor
 * interp` does from its text (tools/interp_times.c, ic_rel_time), so that
 * the same stamps give the tool's samples bit for bit.
 */
#include "path.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* 10^0 .. 10^22, each exact in a double */
static const double pow10_exact[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/* m x 10^p correctly rounded: one exact division or product where m and
 * 10^p are exact doubles, else strtod of the digits */
static double dec_to_double(int64_t m, int p)
{
    const int64_t two53 = (int64_t)1 << 53;
    if (m == 0)
        return 0.0;
    if (m > -two53 && m < two53 && p >= -22 && p <= 22)
        return p < 0 ? (double)m / pow10_exact[-p] : (double)m * pow10_exact[p];
    char b[48];
    snprintf(b, sizeof b, "%lldE%d", (long long)m, p);
    return strtod(b, NULL);
}

/* |m| x k x 10^(e - at) added into the digits d[0..len), right-aligned
 * (len digits, at <= e; the caller leaves room for the carries) */
enum { BIG_DIGITS = 800 };
static void big_acc(int64_t m, uint64_t k, int e, int at, unsigned char *d, int len)
{
    uint64_t u = m < 0 ? (uint64_t)0 - (uint64_t)m : (uint64_t)m;
    unsigned char p[48]; /* |m| x k, least significant digit first: at most 20 + 20 digits */
    int np = 0;
    for (; u; u /= 10) p[np++] = (unsigned char)(u % 10);
    uint64_t carry = 0;
    for (int j = 0; j < np; j++) { /* times k, digit by digit: 9 k + carry < 2^64 for k < 2^59 */
        uint64_t s = (uint64_t)p[j] * k + carry;
        p[j] = (unsigned char)(s % 10);
        carry = s / 10;
    }
    for (; carry; carry /= 10) p[np++] = (unsigned char)(carry % 10);
    int c = 0;
    for (int j = 0, i = len - 1 - (e - at); i >= 0 && (j < np || c); j++, i--) {
        int s = d[i] + (j < np ? p[j] : 0) + c;
        d[i] = (unsigned char)(s % 10);
        c = s / 10;
    }
}

/* (sum of k[j] x x[j]) x 10^shift, j < count, exactly in decimal digits
 * and then strtod (once rounded): where the terms do not fit an int64 at
 * their smallest exponent. |k[j]| < 2^59. */
static double big_sum(const gpy_stamp *x, const int64_t *k, int count, int shift)
{
    int at = INT_MAX, top = INT_MIN;
    for (int j = 0; j < count; j++)
        if (x[j].m && k[j]) {
            at = x[j].e < at ? x[j].e : at;
            top = x[j].e > top ? x[j].e : top;
        }
    if (at == INT_MAX)
        return 0.0;
    int len = top - at + 44;
    if (len > BIG_DIGITS) { /* beyond any double's decimal: not reached */
        double s = 0.0;
        for (int j = 0; j < count; j++) s += (double)k[j] * dec_to_double(x[j].m, x[j].e + shift);
        return s;
    }
    unsigned char pos[BIG_DIGITS], neg[BIG_DIGITS], r[BIG_DIGITS];
    memset(pos, 0, (size_t)len);
    memset(neg, 0, (size_t)len);
    for (int j = 0; j < count; j++) {
        if (!x[j].m || !k[j])
            continue;
        uint64_t ak = k[j] < 0 ? (uint64_t)0 - (uint64_t)k[j] : (uint64_t)k[j];
        big_acc(x[j].m, ak, x[j].e, at, (x[j].m < 0) != (k[j] < 0) ? neg : pos, len);
    }
    /* pos - neg: the larger less the smaller, the sign of the larger */
    int cmp = memcmp(pos, neg, (size_t)len), isneg = cmp < 0;
    const unsigned char *p = cmp >= 0 ? pos : neg, *q = cmp >= 0 ? neg : pos;
    int borrow = 0;
    for (int i = len - 1; i >= 0; i--) {
        int s = p[i] - q[i] - borrow;
        borrow = s < 0;
        r[i] = (unsigned char)(s < 0 ? s + 10 : s);
    }
    char text[BIG_DIGITS + 32];
    int n = 0, i = 0;
    if (isneg)
        text[n++] = '-';
    while (i < len - 1 && r[i] == 0) i++;
    for (; i < len; i++) text[n++] = (char)('0' + r[i]);
    snprintf(text + n, sizeof text - (size_t)n, "E%d", at + shift);
    return strtod(text, NULL);
}

static int times10(int64_t *m)
{
    if (*m > INT64_MAX / 10 || *m < INT64_MIN / 10)
        return 0;
    *m *= 10;
    return 1;
}

#if defined(__SIZEOF_INT128__) && LDBL_MANT_DIG >= 64
/* The fast route, where 128-bit integers and 64-bit long doubles are: a -
 * ref exactly in 128 bits, then m x 10^p approximated in long double with
 * two roundings (m, then the product or quotient by 10^p, exact for
 * |p| <= 27): a relative error below 2^-62. Its double d is the correct
 * rounding unless the approximation lies within that error of the midpoint
 * between d and its neighbour: 1 and *out, or 0 (then the exact routes). */
static int rel_fast(gpy_stamp a, gpy_stamp ref, int shift, double *out)
{
    const __int128 big = (__int128)1 << 120;
    int at = a.e < ref.e ? a.e : ref.e, p;
    __int128 ma = a.m, mb = ref.m;
    for (int e = a.e; e > at; e--)
        if ((ma *= 10) > big || ma < -big)
            return 0;
    for (int e = ref.e; e > at; e--)
        if ((mb *= 10) > big || mb < -big)
            return 0;
    __int128 m = ma - mb;
    p = at + shift;
    if (m == 0) {
        *out = 0.0;
        return 1;
    }
    if (p < -27 || p > 27)
        return 0;
    long double ten = 1.0L;
    for (int k = p < 0 ? -p : p; k > 0; k--) ten *= 10.0L; /* exact: 5^27 < 2^64 */
    long double r = p < 0 ? (long double)m / ten : (long double)m * ten;
    double d = (double)r;
    if (!isnormal(d) || fabs(d) >= DBL_MAX)
        return 0;
    long double diff = r - (long double)d; /* exact */
    double other = nextafter(d, diff >= 0 ? INFINITY : -INFINITY);
    long double mid = ((long double)d + (long double)other) / 2; /* exact */
    if (!(fabsl(mid - r) > fabsl(r) * 0x1p-61L))
        return 0;
    *out = d;
    return 1;
}
#endif

double gpy_stamp_rel(gpy_stamp a, gpy_stamp ref, int ns)
{
#if defined(__SIZEOF_INT128__) && LDBL_MANT_DIG >= 64
    double fast;
    if (rel_fast(a, ref, ns ? -9 : 0, &fast))
        return fast;
#endif
    int shift = ns ? -9 : 0, at = a.e < ref.e ? a.e : ref.e;
    int64_t ma = a.m, mb = ref.m;
    int ok = 1;
    for (int e = a.e; e > at && ok; e--) ok = times10(&ma);
    for (int e = ref.e; e > at && ok; e--) ok = times10(&mb);
    if (ok && !((mb > 0 && ma < INT64_MIN + mb) || (mb < 0 && ma > INT64_MAX + mb)))
        return dec_to_double(ma - mb, at + shift);
    const gpy_stamp x[2] = {a, ref};
    const int64_t k[2] = {1, -1};
    return big_sum(x, k, 2, shift);
}

double gpy_stamp_rel_plus(gpy_stamp a, int64_t k, gpy_stamp c, gpy_stamp ref, int ns)
{
    if (k == 0 || c.m == 0)
        return gpy_stamp_rel(a, ref, ns);
    const gpy_stamp x[3] = {a, c, ref};
    const int64_t kk[3] = {1, k, -1};
    return big_sum(x, kk, 3, ns ? -9 : 0);
}

int gpy_stamp_of_double(double x, int ns, gpy_stamp *s)
{
    uint64_t digits;
    int e;
    if (!isfinite(x))
        return -1;
    ga_double_shortest(x, &digits, &e); /* 17 digits at most: below 2^63 */
    s->m = x < 0 ? -(int64_t)digits : (int64_t)digits;
    s->e = e;
    if (!ns)
        return 0;
    if (e < 0)
        return -2; /* not whole nanoseconds */
    for (; s->e > 0; s->e--)
        if (!times10(&s->m))
            return -3; /* beyond an int64 of nanoseconds */
    return 0;
}

double gpy_stamp_double(gpy_stamp s) { return dec_to_double(s.m, s.e); }

const char *gpy_stamp_text(gpy_stamp s, int ns, char buf[32])
{
    if (ns)
        snprintf(buf, 32, "%lld", (long long)s.m);
    else
        gpy_repr_text(gpy_stamp_double(s), buf);
    return buf;
}

PyArrayObject *gpy_path_times_in(PyObject *obj)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROM_O(obj);
    if (!a)
        return NULL;
    if (PyArray_ISINTEGER(a) && !(PyArray_TYPE(a) == NPY_UINT64 || PyArray_TYPE(a) == NPY_ULONGLONG)) {
        PyArrayObject *r = (PyArrayObject *)PyArray_FROM_OTF((PyObject *)a, NPY_INT64, NPY_ARRAY_CARRAY);
        Py_DECREF(a);
        return r;
    }
    Py_DECREF(a);
    return gpy_as_doubles(obj);
}

int gpy_path_stamp_at(PyArrayObject *a, npy_intp i, int ns, gpy_stamp *s)
{
    if (PyArray_TYPE(a) == NPY_INT64) {
        s->m = ((const int64_t *)PyArray_DATA(a))[i];
        s->e = 0;
        return 0;
    }
    return gpy_stamp_of_double(((const double *)PyArray_DATA(a))[i], ns, s);
}

PyObject *gpy_path_rel_times(gpy_PathObject *self, PyObject *t, PyArrayObject **given)
{
    *given = NULL;
    gpy_stamp ref = self->ref; /* never changes after the build */
    PyArrayObject *a = gpy_path_times_in(t);
    if (!a)
        return NULL;
    if (!self->ns && ref.m == 0 && PyArray_TYPE(a) == NPY_DOUBLE) /* t - 0: t itself */
        return (PyObject *)a;
    PyArrayObject *r = (PyArrayObject *)PyArray_SimpleNew(PyArray_NDIM(a), PyArray_DIMS(a), NPY_DOUBLE);
    if (!r) {
        Py_DECREF(a);
        return NULL;
    }
    double *out = PyArray_DATA(r);
    npy_intp n = PyArray_SIZE(a);
    int isint = PyArray_TYPE(a) == NPY_INT64, ns = self->ns;
    const int64_t *iv = isint ? PyArray_DATA(a) : NULL;
    const double *dv = isint ? NULL : PyArray_DATA(a);
    Py_BEGIN_ALLOW_THREADS; /* C only, on this call's arrays */
    for (npy_intp i = 0; i < n; i++) {
        gpy_stamp s = {isint ? iv[i] : 0, 0};
        if (!isint && gpy_stamp_of_double(dv[i], 0, &s)) /* a NaN or an infinity stays one */
            out[i] = dv[i];
        else
            out[i] = gpy_stamp_rel(s, ref, ns);
    }
    Py_END_ALLOW_THREADS;
    *given = a;
    return (PyObject *)r;
}

PyObject *gpy_stamp_value(gpy_stamp s, int ns)
{
    return ns ? PyLong_FromLongLong((long long)s.m) : PyFloat_FromDouble(gpy_stamp_double(s));
}

int gpy_path_unit(const char *what, const char *name, int *ns)
{
    if (!name || strcmp(name, "s") == 0)
        *ns = 0;
    else if (strcmp(name, "ns") == 0)
        *ns = 1;
    else {
        PyErr_Format(PyExc_ValueError, "%s: time_unit must be 's' or 'ns', not '%s'", what, name);
        return -1;
    }
    return 0;
}

int gpy_path_key_times(const char *what, PyArrayObject *t, int ns, gpy_stamp *stamp, double *rel)
{
    npy_intp n = PyArray_DIM(t, 0);
    for (npy_intp i = 0; i < n; i++) {
        int st = gpy_path_stamp_at(t, i, ns, &stamp[i]);
        char why[200] = "", a[32], b[32];
        char where[64];
        snprintf(where, sizeof where, "%s: times", what);
        if (st == -1) {
            gpy_nonfinite_why("times", t, i, why, sizeof why);
            gpy_raise_status_why(where, 1, &n, i, GA_ERR_NOTFINITE, why);
            return -1;
        }
        if (st) {
            snprintf(why, sizeof why, "%s is not %s (time_unit='ns' takes whole nanoseconds)",
                     gpy_repr_text(((const double *)PyArray_DATA(t))[i], a),
                     st == -2 ? "a whole number" : "within an int64");
            gpy_raise_status_why(where, 1, &n, i, GA_ERR_ARG, why);
            return -1;
        }
        rel[i] = gpy_stamp_rel(stamp[i], stamp[0], ns);
        if (i > 0 && !(rel[i] > rel[i - 1])) {
            snprintf(why, sizeof why, "%s is not after the time before it, %s (times must increase)",
                     gpy_stamp_text(stamp[i], ns, a), gpy_stamp_text(stamp[i - 1], ns, b));
            gpy_raise_status_why(where, 1, &n, i, GA_ERR_ARG, why);
            return -1;
        }
    }
    return 0;
}

size_t gpy_path_key_index(const ga_path *p, double t)
{
    size_t lo = 0, hi = p->n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (p->t[mid] < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < p->n ? lo : p->n - 1;
}
