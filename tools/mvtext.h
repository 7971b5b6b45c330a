/* tools/mvtext.h: multivectors and numbers in the fields of a text line, for
 * the commands that read multivectors written with blade names
 * (`1 + 2e12 - 0.5e45`, docs/conventions.md: ga_mv_parse and ga_mv_format),
 * with errors naming the line and the column where the text goes wrong. A
 * line's fields are separated by ';'. */
#ifndef GAROTOR_TOOLS_MVTEXT_H
#define GAROTOR_TOOLS_MVTEXT_H

#include <stddef.h>

#include <garotor/garotor.h>

#include "textio.h"

/** A field of line i of t: bytes [at, at + len) of t->text[i]. */
typedef struct {
    size_t at, len;
} mvt_field;

/** Split line i at ';' into at most max fields (into f); the number of
 *  fields, or -1 after a message when there are more than max. */
int mvt_fields(const tio_texts *t, size_t i, mvt_field *f, int max);

/** The multivector written in field f of line i (ga_mv_parse): 0, or -1
 *  after a message naming the column of the term that is wrong. */
int mvt_parse(const tio_texts *t, size_t i, mvt_field f, ga_mv *out);

/** The numbers of field f of line i from byte `from` of it (separated by
 *  blanks or commas; finite, as the tool's numbers): their count (at most
 *  max are stored in v; more are counted), or -1 after a message. */
int mvt_numbers(const tio_texts *t, size_t i, mvt_field f, size_t from, double *v, int max);

/** a as text into buf (GA_MV_TEXT_MAX bytes): its length, or 0 when a
 *  coefficient is not finite. */
size_t mvt_format(ga_mv a, char *buf);

#endif
