/* bench/inputs.c: the inputs of garotor-bench: a seeded PRNG (xoshiro256**),
 * random twists, rotors and points in the rings, general 4x4 matrices with
 * their principal logs, the tables of the floor gp_table, the paths the
 * sampling cases walk, and the pairs of objects the meet cases meet.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

/* ---- PRNG: xoshiro256**, seeded by splitmix64 --------------------------- */

static uint64_t rng_s[4];

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

void rng_seed(uint64_t seed)
{
    for (int i = 0; i < 4; i++) rng_s[i] = splitmix64(&seed);
}

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static uint64_t rng_next(void)
{
    uint64_t r = rotl(rng_s[1] * 5, 7) * 9, t = rng_s[1] << 17;
    rng_s[2] ^= rng_s[0];
    rng_s[3] ^= rng_s[1];
    rng_s[1] ^= rng_s[2];
    rng_s[0] ^= rng_s[3];
    rng_s[2] ^= t;
    rng_s[3] = rotl(rng_s[3], 45);
    return r;
}

/* uniform in [a, b) */
static double uniform(double a, double b)
{
    return a + (b - a) * ((double)(rng_next() >> 11) * (1.0 / 9007199254740992.0));
}

static ga_vec3 random_unit(void)
{
    for (;;) {
        ga_vec3 v = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        double n2 = v.x * v.x + v.y * v.y + v.z * v.z;
        if (n2 > 1e-4 && n2 <= 1.0) {
            double k = 1.0 / sqrt(n2);
            ga_vec3 u = {k * v.x, k * v.y, k * v.z};
            return u;
        }
    }
}

/* A twist of rotation angle uniform in [0.05, 3.0] rad about a uniform axis
 * and a translation part uniform in [-2, 2]^3. */
static ga_twist random_twist(void)
{
    ga_vec3 u = random_unit();
    double th = uniform(0.05, 3.0);
    ga_twist xi = {{th * u.x, th * u.y, th * u.z}, {uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)}};
    return xi;
}

static ga_rotor rotor_of_twist(ga_twist xi) { return ga_rotor_exp(ga_twist_to_generator(xi)); }

/* The tables of the floor gp_table (floors.h): the sign and the blade of
 * e_i e_j, by ga_blade_mask and the swap-counting rule. */
static void gp_tables(void)
{
    int index_of[32];
    for (int i = 0; i < 32; i++) index_of[ga_blade_mask(i)] = i;
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) {
            unsigned a = ga_blade_mask(i), b = ga_blade_mask(j);
            int swaps = 0;
            for (unsigned x = a >> 1; x; x >>= 1)
                for (unsigned y = x & b; y; y &= y - 1) swaps++;
            if (a & b & 0x10u) /* e5 e5 = -1 */
                swaps++;
            gp_sign[i][j] = (swaps & 1) ? -1.0 : 1.0;
            gp_index[i][j] = (unsigned char)index_of[a ^ b];
        }
}

/* ---- paths ----------------------------------------------------------------- */

static ga_rotor key_rotors[N_PATHS][N_KEYS];

static int build_paths(void)
{
    double times[N_KEYS];
    ga_mat4 keys[N_KEYS];
    for (int i = 0; i < N_KEYS; i++) times[i] = i;
    for (int p = 0; p < N_PATHS; p++) {
        for (int i = 0; i < N_KEYS; i++) {
            ga_rotor r = rotor_of_twist(random_twist());
            ga_vec3 t = ga_rotor_to_translation(r);
            ga_quat q = ga_rotor_to_quat(r);
            double pose[7] = {t.x, t.y, t.z, q.x, q.y, q.z, q.w};
            key_rotors[p][i] = r;
            keys[i] = ga_rotor_to_mat4(r);
            memcpy(key_poses[p][i], pose, sizeof pose);
        }
        for (int k = 0; k < N_PATH_KINDS; k++) {
            const ga_group *g = path_kind[k].group;
            size_t bytes = ga_path_workspace_size(g, path_kind[k].scheme, N_KEYS);
            void *work = malloc(bytes);
            if (!work)
                return GA_ERR_ARG;
            int st = ga_path_init_mat4(g, path_kind[k].scheme, N_KEYS, times, keys, NULL, work, bytes,
                                       &paths[k][p]);
            if (st != GA_OK)
                return st;
        }
    }
    return GA_OK;
}

/* ---- the pairs of objects of the meet cases (cases_meet.c) ------------------ */

static ga_vec3 random_point(double a, double b)
{
    ga_vec3 x = {uniform(a, b), uniform(a, b), uniform(a, b)};
    return x;
}

static ga_vec3 add3(ga_vec3 a, ga_vec3 b, double s)
{
    ga_vec3 r = {a.x + s * b.x, a.y + s * b.y, a.z + s * b.z};
    return r;
}

/* A sphere through 4 random points of the sphere of centre c and radius r. */
static ga_mv sphere_on(ga_vec3 c, double r)
{
    ga_vec3 p[4];
    for (int k = 0; k < 4; k++) p[k] = add3(c, random_unit(), r);
    return ga_sphere_from_points(p[0], p[1], p[2], p[3]);
}

/* A plane through 3 random points within s (per axis) of c. */
static ga_mv plane_near(ga_vec3 c, double s)
{
    ga_vec3 p[3];
    for (int k = 0; k < 3; k++) p[k] = add3(c, random_point(-s, s), 1.0);
    return ga_plane_from_points(p[0], p[1], p[2]);
}

/* Slot j of pair p, drawn from random points until the meet reads back
   (GA_OK) as the pair's kind, real: planes and lines through points of
   [-5, 5]^3; spheres of radius in [0.5, 2] centred in [-2, 2]^3, the second
   at a distance that makes their circle real, the plane of plane_sphere
   within half the radius of the sphere's centre (per axis): a real circle. */
static int meet_pair(int p, int j)
{
    for (int tries = 0; tries < 100; tries++) {
        ga_vec3 c = random_point(-2, 2);
        double r = uniform(0.5, 2.0), r2 = uniform(0.5, 2.0);
        ga_mv a, b;
        switch (p) {
        case MP_PLANE_PLANE:
            a = plane_near(c, 5.0);
            b = plane_near(c, 5.0);
            break;
        case MP_LINE_PLANE:
            a = ga_line_from_points(random_point(-5, 5), random_point(-5, 5));
            b = plane_near(c, 5.0);
            break;
        case MP_SPHERE_SPHERE: {
            double lo = fabs(r - r2) + 0.1, hi = r + r2 - 0.1;
            a = sphere_on(c, r);
            b = sphere_on(add3(c, random_unit(), uniform(lo, hi)), r2);
            break;
        }
        default:
            a = plane_near(c, 0.5 * r);
            b = sphere_on(c, r);
            break;
        }
        ga_mv w = ga_mv_meet(a, b);
        ga_object o;
        if (ga_object_from_mv(w, &o) != GA_OK || o.kind != meet_pair_kind[p] || o.reality != GA_REALITY_REAL)
            continue;
        meet_a[p][j] = a;
        meet_b[p][j] = b;
        meet_w[p][j] = w;
        return GA_OK;
    }
    return GA_ERR_SINGULAR;
}

int setup_inputs(void)
{
    for (int j = 0; j < RING; j++) {
        for (int i = 0; i < 32; i++) {
            mv_a[j].c[i] = uniform(-1, 1);
            mv_b[j].c[i] = uniform(-1, 1);
        }
        twists[j] = random_twist();
        gens[j] = ga_twist_to_generator(twists[j]);
        rot_a[j] = ga_rotor_exp(gens[j]);
        rot_b[j] = rotor_of_twist(random_twist());
        dq_a[j] = ga_rotor_to_dualquat(rot_a[j]);
        dq_b[j] = ga_rotor_to_dualquat(rot_b[j]);
        rigid_a[j] = ga_rotor_to_mat4(rot_a[j]);
        rigid_b[j] = ga_rotor_to_mat4(rot_b[j]);
        hats[j] = ga_twist_hat(twists[j]);
        ga_vec3 x = {uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)};
        pts[j] = x;
        /* a general real 4x4 generator: entries uniform in [-0.7, 0.7], last
           row zero; its exp is a general invertible homogeneous matrix whose
           principal log is the generator again (eigenvalues well inside the
           strip |Im| < pi) */
        for (;;) {
            ga_mat4 a;
            for (int i = 0; i < 16; i++) a.m[i] = i < 12 ? uniform(-0.7, 0.7) : 0.0;
            ga_mat4 e, l;
            if (ga_mat4_expm(a, &e) != GA_OK || ga_mat4_logm(e, &l) != GA_OK || maxdiff(l.m, a.m, 16) > 1e-9)
                continue;
            gen_x[j] = a;
            gen_m[j] = e;
            break;
        }
    }
    /* the same motions and points as full multivectors (no new draws: the
       rings above stay those of earlier runs) */
    for (int j = 0; j < RING; j++) {
        mv_rot[j] = ga_rotor_to_mv(rot_a[j]);
        mv_rot_rev[j] = ga_mv_reverse(mv_rot[j]);
        mv_pt[j] = ga_point_up(pts[j]);
        for (int i = 0, k = 0; i < 32; i++)
            if (ga_blade_grade(i) % 2 == 0)
                even_rot[j][k++] = mv_rot[j].c[i];
        for (int i = 0; i < 5; i++) vec_pt[j][i] = mv_pt[j].c[1 + i];
    }
    gp_tables();
    int st = build_paths();
    /* the meets' pairs after every other draw: the rings above stay those of
       earlier runs */
    if (st == GA_OK)
        st = meet_check_dual();
    for (int p = 0; p < N_MEET_PAIRS && st == GA_OK; p++)
        for (int j = 0; j < RING && st == GA_OK; j++) st = meet_pair(p, j);
    return st;
}
