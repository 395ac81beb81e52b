#include "MedialErrorCollector.h"

namespace medial {

vtkSmartPointer<ErrorCollector> ErrorCollector::Watch(vtkObject* object, bool warningsToo) {
  auto collector = vtkSmartPointer<ErrorCollector>::New();
  object->AddObserver(vtkCommand::ErrorEvent, collector);
  if (warningsToo) object->AddObserver(vtkCommand::WarningEvent, collector);
  return collector;
}

void ErrorCollector::Execute(vtkObject*, unsigned long, void* callData) {
  if (callData) Errors.push_back(StripVtkPrefix(static_cast<const char*>(callData)));
}

std::string ErrorCollector::Joined() const {
  std::string all;
  for (const std::string& e : Errors) all += (all.empty() ? "" : "; ") + e;
  return all;
}

std::string ErrorCollector::StripVtkPrefix(const std::string& message) {
  std::string text = message;
  // vtkErrorMacro text: "ERROR: In <file>, line <n>\n<class> (<address>): <message>\n\n"
  const size_t newline = text.find('\n');
  if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0) {
    if (newline != std::string::npos) text = text.substr(newline + 1);
    const size_t colon = text.find("): ");
    if (colon != std::string::npos) text = text.substr(colon + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

}  // namespace medial
