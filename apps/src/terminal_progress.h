#pragma once
// Progress bars for long commands (decompose, audit, bench): drawn on
// stderr only when stderr is a terminal and the user did not ask for quiet,
// so logs, pipes and CI stay clean. No Debian package offers a C++ progress
// bar; this is the few lines the commands need.

#include <cstdio>
#include <string>

namespace hullcover::app {

/// One progress bar on stderr, redrawn in place.
class TerminalProgress {
public:
  /// A bar labelled `label`; drawn only when `quiet` is false and stderr is
  /// a terminal.
  TerminalProgress(std::string label, bool quiet);
  ~TerminalProgress();
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  /// Whether the bar is drawn at all.
  bool enabled() const { return enabled_; }
  /// Shows `fraction` (0..1, clamped) done; redraws only when the shown
  /// per-mille changes, so a tight loop may call it freely.
  void update(double fraction);
  /// Changes the label (the next update draws it).
  void relabel(std::string label);
  /// Ends the bar's line (once; the destructor does it too).
  void finish();
  /// Prints `line` above the bar (a result worth keeping on screen); prints
  /// nothing when the bar is not drawn.
  void note(const std::string& line);

private:
  void draw();

  std::string label_;
  bool enabled_ = false;
  bool drawn_ = false;
  int shown_ = -1; // per mille last drawn
};

} // namespace hullcover::app
