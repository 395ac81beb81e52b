#include "Progress.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkSmartPointer.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace medial::cli {

namespace {
bool progressAsLines() {
  const char* mode = std::getenv("MEDIAL_PROGRESS");
  return mode && std::strcmp(mode, "lines") == 0;
}
}  // namespace

ProgressLine::ProgressLine(bool quiet)
    : enabled_(!quiet && (progressAsLines() || ::isatty(STDERR_FILENO))), asLines_(progressAsLines()) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::watch(vtkAlgorithm* algorithm, const std::string& label) {
  if (!enabled_) return;
  struct Context {
    ProgressLine* line;
    std::string label;
  };
  auto* context = new Context{this, label};
  auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
  callback->SetClientData(context);
  callback->SetClientDataDeleteCallback([](void* data) { delete static_cast<Context*>(data); });
  callback->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* c = static_cast<Context*>(clientData);
    c->line->show(c->label, *static_cast<double*>(callData));
  });
  algorithm->AddObserver(vtkCommand::ProgressEvent, callback);
  show(label, 0.0);
}

void ProgressLine::show(const std::string& label, double fraction) {
  if (!enabled_) return;
  const int percent = static_cast<int>(fraction * 100.0 + 0.5);
  if (drawn_ && percent == lastPercent_) return;
  lastPercent_ = percent;
  if (asLines_)
    std::fprintf(stderr, "medial-progress %s %d\n", label.c_str(), percent);
  else
    std::fprintf(stderr, "\r\033[K%s %3d%%", label.c_str(), percent);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  if (enabled_ && drawn_ && !asLines_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
  drawn_ = false;
  lastPercent_ = -1;
}

}  // namespace medial::cli
