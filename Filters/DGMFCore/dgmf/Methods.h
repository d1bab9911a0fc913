/**
 * @file Methods.h
 * @brief The deformation methods and their names: one table (MethodTable.def) for the VTK filter,
 * the ParaView XML, the command line and the benchmark.
 */
#ifndef dgmf_Methods_h
#define dgmf_Methods_h

#include <string>
#include <vector>

namespace dgmf
{

/// The deformation methods; the values are the filter's Method property.
enum class Method : int
{
#define DGMF_METHOD(value, name, key, graph, description) name = value,
#include "dgmf/MethodTable.def"
#undef DGMF_METHOD
};

/// One method as the user names it.
struct MethodInfo
{
  Method Id;
  const char* Name;        ///< "DGMF": the ParaView choice, the field data's Method string
  const char* Key;         ///< "dgmf": the command line and the benchmark
  bool UsesGraph;          ///< needs the Delaunay graph of the boundary nodes
  const char* Description; ///< the method and its reference
};

/// Every method, in increasing value.
const std::vector<MethodInfo>& GetMethods();

/// The entry of `method`.
const MethodInfo& GetMethodInfo(Method method);

/// The method whose value is `value` (the filter's Method property), or null.
const MethodInfo* FindMethod(int value);

/// The method named `name` (its Name or Key, any case), or null.
const MethodInfo* FindMethod(const std::string& name);

/// The Keys of all methods, separated by `separator` ("dgmf, dgm, ..."), for help and errors.
std::string ListMethodKeys(const std::string& separator);

} // namespace dgmf

#endif
