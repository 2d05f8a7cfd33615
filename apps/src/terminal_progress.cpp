#include "terminal_progress.h"

#include <algorithm>
#include <cmath>
#include <unistd.h>

namespace hullcover::app {
namespace {

constexpr int kBarWidth = 30;   // characters between the brackets
constexpr int kPerMille = 1000; // the bar's resolution

} // namespace

TerminalProgress::TerminalProgress(std::string label, bool quiet)
    : label_(std::move(label)), enabled_(!quiet && isatty(STDERR_FILENO) == 1) {}

TerminalProgress::~TerminalProgress() { finish(); }

void TerminalProgress::update(double fraction) {
  if (!enabled_) return;
  const double clamped = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  const int per_mille = static_cast<int>(std::floor(clamped * kPerMille));
  if (per_mille == shown_) return;
  shown_ = per_mille;
  draw();
}

void TerminalProgress::relabel(std::string label) {
  label_ = std::move(label);
  shown_ = -1;
}

void TerminalProgress::draw() {
  const int filled = shown_ * kBarWidth / kPerMille;
  // \r and clear-to-end-of-line: the bar overwrites itself.
  std::fprintf(stderr, "\r\033[K[%s%s] %5.1f%% %s", std::string(filled, '#').c_str(),
               std::string(kBarWidth - filled, '.').c_str(), shown_ / 10.0, label_.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void TerminalProgress::finish() {
  if (enabled_ && drawn_) std::fputc('\n', stderr);
  drawn_ = false;
}

void TerminalProgress::note(const std::string& line) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r\033[K%s\n", line.c_str());
  if (shown_ >= 0) draw();
}

} // namespace hullcover::app
