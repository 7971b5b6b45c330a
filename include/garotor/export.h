/* garotor/export.h: the markers on garotor's public declarations.
 *
 *   GA_API        the symbol is part of the library's ABI. The library is
 *                 built with hidden visibility: what is not marked GA_API is
 *                 not exported, so the library's own files share helpers
 *                 through internal headers without widening the ABI.
 *   GA_NODISCARD  the function returns a status (ga_status) that must be
 *                 read: ignoring it is a compiler warning.
 *
 * On Windows, define GAROTOR_STATIC when linking the static library; the
 * library's own build defines GAROTOR_BUILDING.
 */
#ifndef GAROTOR_EXPORT_H
#define GAROTOR_EXPORT_H

#if defined(_WIN32) || defined(__CYGWIN__)
#if defined(GAROTOR_BUILDING)
#define GA_API __declspec(dllexport)
#elif defined(GAROTOR_STATIC)
#define GA_API
#else
#define GA_API __declspec(dllimport)
#endif
#elif defined(__GNUC__) && __GNUC__ >= 4
#define GA_API __attribute__((visibility("default")))
#else
#define GA_API
#endif

#if defined(__GNUC__) && __GNUC__ >= 4
#define GA_NODISCARD __attribute__((warn_unused_result))
#elif defined(_MSC_VER) && _MSC_VER >= 1700
#define GA_NODISCARD _Check_return_
#else
#define GA_NODISCARD
#endif

#endif
