/// \file
/// MedialErrorCollector: gathers the messages of vtkErrorMacro calls made by an observed VTK object, without
/// VTK's "ERROR: In file, line N / class (address):" prefix, so that the CLI and the GUI can show one clean
/// line and a filter can forward a nested reader's complaint.
#pragma once

#include <vtkCommand.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace medial {

/// A vtkCommand that collects the clean messages of the errors (and warnings) an object reports.
class ErrorCollector : public vtkCommand {
 public:
  ///@{
  /// VTK's object protocol.
  static ErrorCollector* New() { return new ErrorCollector; }
  vtkBaseTypeMacro(ErrorCollector, vtkCommand);
  ///@}

  /// Observes ErrorEvent (and WarningEvent when asked) on `object`.
  static vtkSmartPointer<ErrorCollector> Watch(vtkObject* object, bool warningsToo = false);

  /// vtkCommand: keeps the message of an ErrorEvent (or WarningEvent), its VTK prefix removed.
  void Execute(vtkObject* caller, unsigned long eventId, void* callData) override;

  /// True when a message was collected.
  bool HasErrors() const { return !Errors.empty(); }
  /// The messages, in the order they came.
  const std::vector<std::string>& GetErrors() const { return Errors; }
  /// All messages joined by "; ", or an empty string.
  std::string Joined() const;
  /// Forgets the messages collected so far.
  void Clear() { Errors.clear(); }

  /// Removes VTK's "ERROR: In ..., line N\nclass (0x...): " prefix from a message.
  static std::string StripVtkPrefix(const std::string& message);

 private:
  std::vector<std::string> Errors;
};

}  // namespace medial
