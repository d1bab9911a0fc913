#include "DGMFCommandMessages.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkTimerLog.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <mutex>
#include <set>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace dgmf_cli
{
namespace
{
std::atomic<int> ErrorCount(0); // VTK reports from worker threads too (a compressor's error)
// Read by the signal handlers: fixed buffers, not std::string.
char Stage[1024] = "";
char WrittenSoFar[512] = "nothing was written";
char TemporaryFile[4096] = "";

void CopyTo(char* buffer, std::size_t size, const std::string& text)
{
  const std::size_t n = std::min(text.size(), size - 1);
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\0';
}

/**
 * "ERROR: In /path/file.cxx, line 12\nvtkClass (0x1234): the text\n\n" -> "the text": VTK's
 * location and object prefix mean nothing to a user of the command.
 */
std::string MessageText(const char* vtkText)
{
  std::string text = vtkText ? vtkText : "";
  if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
    text.rfind("Generic Warning: In ", 0) == 0)
  {
    const std::size_t newline = text.find('\n');
    text = newline == std::string::npos ? "" : text.substr(newline + 1);
  }
  const std::size_t object = text.find("): ");
  if (object != std::string::npos && text.find(" (0x") < object)
  {
    text = text.substr(object + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}

/// The output window of dgmf-deform: one line per message, on stderr.
class CommandOutputWindow : public vtkOutputWindow
{
public:
  static CommandOutputWindow* New();
  vtkTypeMacro(CommandOutputWindow, vtkOutputWindow);

  void DisplayText(const char* text) override { this->Print("", text); }
  void DisplayErrorText(const char* text) override
  {
    ++ErrorCount;
    this->Print("error: ", text);
  }
  void DisplayWarningText(const char* text) override { this->Print("warning: ", text); }
  void DisplayGenericWarningText(const char* text) override { this->Print("warning: ", text); }
  void DisplayDebugText(const char*) override {}

  /// Messages printed from now on are printed even if they were before.
  void Forget()
  {
    const std::lock_guard<std::mutex> lock(this->Lock);
    this->Printed.clear();
  }

  /// `text` is shown as `shown` in the messages printed from now on.
  void AddAlias(const std::string& text, const std::string& shown)
  {
    const std::lock_guard<std::mutex> lock(this->Lock);
    this->Aliases.emplace_back(text, shown);
  }

private:
  void Print(const char* kind, const char* vtkText)
  {
    // VTK's messages may come from several threads at once (a decompressor on each).
    const std::lock_guard<std::mutex> lock(this->Lock);
    std::string text = MessageText(vtkText);
    for (const auto& alias : this->Aliases)
    {
      for (std::size_t at = text.find(alias.first); at != std::string::npos;
           at = text.find(alias.first, at + alias.second.size()))
      {
        text.replace(at, alias.first.size(), alias.second);
      }
    }
    // The executive's report that an algorithm failed repeats what the algorithm said, followed
    // by a dump of the pipeline request.
    if (text.empty() || text.find("returned failure for request") != std::string::npos ||
      !this->Printed.insert(std::string(kind) + text).second)
    {
      return;
    }
    std::cerr << "dgmf-deform: " << kind << text << std::endl;
  }

  std::set<std::string> Printed;
  std::vector<std::pair<std::string, std::string>> Aliases;
  std::mutex Lock;
};
vtkStandardNewMacro(CommandOutputWindow);

void Write(const char* text)
{
  const ssize_t ignored = write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

/// Async-signal-safe: only write, unlink and _exit.
extern "C" void OnFatalSignal(int signal)
{
  if (TemporaryFile[0] != '\0')
  {
    unlink(TemporaryFile);
  }
  if (signal == SIGABRT)
  {
    Write("dgmf-deform: error: VTK stopped the program while ");
    Write(Stage[0] != '\0' ? Stage : "working");
    Write(" (it aborts when memory runs out: see the message above); ");
    Write(WrittenSoFar);
    Write(".\n");
    _exit(1);
  }
  Write("dgmf-deform: interrupted while ");
  Write(Stage[0] != '\0' ? Stage : "working");
  Write("; ");
  Write(WrittenSoFar);
  Write(".\n");
  _exit(128 + signal);
}
} // namespace

void InstallMessageWindow()
{
  vtkNew<CommandOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  // VTK also logs every error and warning through vtkLogger, in colour, with the object's address.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

void ForgetPrintedMessages()
{
  if (auto* window = CommandOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance()))
  {
    window->Forget();
  }
}

void ShowInMessagesAs(const std::string& text, const std::string& shown)
{
  if (auto* window = CommandOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance()))
  {
    window->AddAlias(text, shown);
  }
}

int GetErrorCount()
{
  return ErrorCount;
}

void ResetErrorCount()
{
  ErrorCount = 0;
}

void SetStage(const std::string& stage)
{
  CopyTo(Stage, sizeof(Stage), stage);
}

void SetWrittenSoFar(const std::string& written)
{
  CopyTo(WrittenSoFar, sizeof(WrittenSoFar), written);
}

void SetTemporaryFile(const std::string& path)
{
  CopyTo(TemporaryFile, sizeof(TemporaryFile), path);
}

void InstallSignalHandlers()
{
  for (int signal : { SIGABRT, SIGINT, SIGTERM, SIGHUP })
  {
    std::signal(signal, OnFatalSignal);
  }
  std::signal(SIGXFSZ, SIG_IGN);
}

void ShowProgress(vtkAlgorithm* algorithm, const std::string& what, double delaySeconds)
{
  struct State
  {
    std::string What;
    double Delay = 0.0;
    double Start = 0.0;
    int LastTenth = -1;
  };
  auto* state = new State{ what, delaySeconds, vtkTimerLog::GetUniversalTime(), -1 };
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(state);
  onProgress->SetClientDataDeleteCallback([](void* data) { delete static_cast<State*>(data); });
  onProgress->SetCallback(
    [](vtkObject*, unsigned long, void* data, void* callData)
    {
      auto* s = static_cast<State*>(data);
      const double fraction = callData ? *static_cast<double*>(callData) : 0.0;
      const int tenth = static_cast<int>(fraction * 10.0);
      if (tenth > s->LastTenth && tenth < 10 &&
        vtkTimerLog::GetUniversalTime() - s->Start >= s->Delay)
      {
        s->LastTenth = tenth;
        std::cerr << "dgmf-deform: " << s->What << " " << 10 * tenth << "%" << std::endl;
      }
    });
  algorithm->AddObserver(vtkCommand::ProgressEvent, onProgress);
}
} // namespace dgmf_cli
