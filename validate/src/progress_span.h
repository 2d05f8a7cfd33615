#pragma once
/// \file progress_span.h
/// One stage's share of a progress report (movement_audit.h's progress):
/// the stage reports its own fraction, the caller's report gets its place
/// in the whole.

#include <functional>

namespace hullcover::validate::detail {

/// Reports a stage's fraction f as `start + share * f` to `whole` (which
/// must outlive the report); empty when `whole` is, so a stage can skip the
/// reporting's work.
inline std::function<void(double)> progress_span(const std::function<void(double)>& whole, double start, double share) {
  if (!whole) return {};
  return [&whole, start, share](double fraction) { whole(start + share * fraction); };
}

} // namespace hullcover::validate::detail
