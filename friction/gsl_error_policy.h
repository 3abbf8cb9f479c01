#pragma once
// GSL's default error handler aborts the process. frictionlab checks every GSL status code
// itself and reports failures as exceptions or run summaries, so the handler is switched off —
// once, process-wide, thread-safely (GSL keeps it in a global; flipping it per call from several
// threads would be a data race).

#include <gsl/gsl_errno.h>

namespace frictionlab {

inline void use_gsl_status_codes() {
  static const bool done = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)done;
}

}  // namespace frictionlab
