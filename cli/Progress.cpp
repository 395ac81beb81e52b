#include "Progress.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkSmartPointer.h>

#include <cstdio>
#include <unistd.h>

namespace medial::cli {

ProgressLine::ProgressLine(bool quiet) : enabled_(!quiet && ::isatty(STDERR_FILENO)) {}

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
  std::fprintf(stderr, "\r\033[K%s %3d%%", label.c_str(), percent);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  if (enabled_ && drawn_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
  drawn_ = false;
  lastPercent_ = -1;
}

}  // namespace medial::cli
