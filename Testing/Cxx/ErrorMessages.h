/**
 * @file ErrorMessages.h
 * @brief The error messages a VTK object emits, collected for a test to look into.
 */
#ifndef dgmf_test_ErrorMessages_h
#define dgmf_test_ErrorMessages_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <string>
#include <vector>

namespace dgmf_test
{

/// Collects the error messages of `object` (its ErrorEvents, or the `event` given:
/// vtkCommand::WarningEvent for its warnings) from construction on.
struct ErrorMessages
{
  std::vector<std::string> Messages;
  vtkNew<vtkCallbackCommand> Callback;

  explicit ErrorMessages(vtkObject* object, unsigned long event = vtkCommand::ErrorEvent)
  {
    this->Callback->SetClientData(&this->Messages);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long, void* data, void* text) {
        static_cast<std::vector<std::string>*>(data)->emplace_back(static_cast<const char*>(text));
      });
    object->AddObserver(event, this->Callback);
  }

  /// True when a message contains `text`.
  bool Contains(const std::string& text) const
  {
    for (const std::string& message : this->Messages)
    {
      if (message.find(text) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
};

} // namespace dgmf_test

#endif
