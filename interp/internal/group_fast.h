/* interp/internal/group_fast.h (internal, not installed): optional fast
 * operations of a group, which interp's scheme code calls where the group
 * has them and does the generic work through group.h otherwise. The public
 * ga_group stays as it is: a group a user defines has none, and so do the
 * library's groups without one (gai_group_fast_of gives NULL).
 * Prefix gai_; nothing here is exported.
 */
#ifndef GA_INTERP_INTERNAL_GROUP_FAST_H
#define GA_INTERP_INTERNAL_GROUP_FAST_H

#include <garotor/group.h>

typedef struct gai_group_fast {
    /* The screw A exp(u x) sampled at many u on one segment (SCREW): the
     * group's own closed form, prepared once per segment. screw_prep reads
     * the key A and the algebra element x into three buffers of
     * GA_GROUP_MAX_ELEM doubles each (their layout is the group's);
     * screw_at writes A exp(u x) from them, GA_OK, or GA_ERR_DOMAIN where
     * the result is not finite. screw_step, for stepping along the screw:
     * a = a e in place by g->compose's product (the same bits), then out =
     * a, GA_OK, or GA_ERR_DOMAIN where it is not finite. The schemes use
     * the three together or, where one is NULL, the generic g->exp and
     * g->compose. */
    void (*screw_prep)(const void *a, const double *x, double *p0, double *p1, double *p2);
    int (*screw_at)(const double *p0, const double *p1, const double *p2, double u, void *out);
    int (*screw_step)(void *a, const void *e, void *out);
} gai_group_fast;

/* The groups' tables (group_cga.c has one; se3 and affine have none). */
extern const gai_group_fast gig_cga_fast;

/* The fast operations of g, or NULL (any group but the library's own, and
 * those of the library's groups that have none). Inline: a sampler asks it
 * for every sample. */
static inline const gai_group_fast *gai_group_fast_of(const ga_group *g)
{
    return g == &ga_group_cga ? &gig_cga_fast : NULL;
}

#endif
