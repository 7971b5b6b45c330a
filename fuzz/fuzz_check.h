/* fuzz/fuzz_check.h: how a fuzz target reports a broken invariant.
 *
 * FZ_CHECK(cond, fmt, ...) reports "fuzz invariant broken at FILE:LINE:
 * cond: message" and aborts; libFuzzer records that as a crash and saves the
 * input. Under a sanitizer the message goes through the sanitizer runtime's
 * report channel (__sanitizer_report_error_summary), so it is seen even under
 * -close_fd_mask=2, which the tool target uses to silence the tool's own
 * error messages; elsewhere (the replay build of the default test suite) to
 * standard error. */
#ifndef GAROTOR_FUZZ_CHECK_H
#define GAROTOR_FUZZ_CHECK_H

#include <stdio.h>
#include <stdlib.h>

#if defined(__SANITIZE_ADDRESS__)
#define FZ_HAVE_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FZ_HAVE_SANITIZER 1
#endif
#endif

#ifdef FZ_HAVE_SANITIZER
#include <sanitizer/common_interface_defs.h>
#define FZ_REPORT(msg) __sanitizer_report_error_summary(msg)
#else
#define FZ_REPORT(msg) fprintf(stderr, "%s\n", msg)
#endif

#define FZ_CHECK(cond, ...)                                                                                  \
    do {                                                                                                     \
        if (!(cond)) {                                                                                       \
            char fz_msg_[1024];                                                                              \
            int fz_k_ = snprintf(fz_msg_, sizeof fz_msg_, "fuzz invariant broken at %s:%d: %s: ", __FILE__,  \
                                 __LINE__, #cond);                                                           \
            if (fz_k_ > 0 && (size_t)fz_k_ < sizeof fz_msg_)                                                 \
                snprintf(fz_msg_ + fz_k_, sizeof fz_msg_ - (size_t)fz_k_, __VA_ARGS__);                      \
            FZ_REPORT(fz_msg_);                                                                              \
            abort();                                                                                         \
        }                                                                                                    \
    } while (0)

#endif
