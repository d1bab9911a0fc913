#include "dgmf/Methods.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace dgmf
{

const std::vector<MethodInfo>& GetMethods()
{
  static const std::vector<MethodInfo> methods = {
#define DGMF_METHOD(value, name, key, graph, description)                                          \
  MethodInfo{ Method::name, #name, #key, graph, description },
#include "dgmf/MethodTable.def"
#undef DGMF_METHOD
  };
  return methods;
}

const MethodInfo& GetMethodInfo(Method method)
{
  for (const MethodInfo& info : GetMethods())
  {
    if (info.Id == method)
    {
      return info;
    }
  }
  throw std::invalid_argument(
    "unknown deformation method " + std::to_string(static_cast<int>(method)));
}

const MethodInfo* FindMethod(int value)
{
  for (const MethodInfo& info : GetMethods())
  {
    if (static_cast<int>(info.Id) == value)
    {
      return &info;
    }
  }
  return nullptr;
}

const MethodInfo* FindMethod(const std::string& name)
{
  const auto lower = [](std::string text)
  {
    std::transform(text.begin(), text.end(), text.begin(),
      [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
  };
  const std::string wanted = lower(name);
  for (const MethodInfo& info : GetMethods())
  {
    if (wanted == lower(info.Name) || wanted == lower(info.Key))
    {
      return &info;
    }
  }
  return nullptr;
}

std::string ListMethodKeys(const std::string& separator)
{
  std::string list;
  for (const MethodInfo& info : GetMethods())
  {
    list += (list.empty() ? "" : separator) + std::string(info.Key);
  }
  return list;
}

} // namespace dgmf
