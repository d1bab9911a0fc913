/*
 * dgmf_expat_fix: a work-around for Debian 12's libexpat (2.5.0-1+deb12u2 and later).
 *
 * Those builds back-port the CVE-2023-52425 fix, which defers re-parsing of partial input.
 * VTK 9.2's vtkXMLParser feeds expat in pieces without turning the deferral off, so appended-mode
 * .vtu files read back as empty and ParaView's MPI redistribution silently drops data.
 *
 * This library wraps the parser constructors and turns the deferral off on every new parser
 * (XML_SetReparseDeferralEnabled(parser, XML_FALSE)), as later VTK releases do. With an expat that
 * has no such function it does nothing. Use it with LD_PRELOAD for pvpython, pvbatch and paraview,
 * or link it into an executable (it then comes before libexpat in the symbol lookup).
 *
 * The DGMF plugin looks for the marker dgmf_expat_fix_loaded in the library that serves
 * XML_ParserCreate, to warn when ParaView runs without this work-around (Plugin/DGMFExpatCheck.h).
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <expat.h>

/** Marker: this library is loaded (the plugin finds it with dlsym, see DGMFExpatCheck.h). */
__attribute__((visibility("default"))) const int dgmf_expat_fix_loaded = 1;

typedef XML_Parser (*CreateFunction)(const XML_Char*);
typedef XML_Parser (*CreateNSFunction)(const XML_Char*, XML_Char);
typedef XML_Parser (*CreateMMFunction)(
  const XML_Char*, const XML_Memory_Handling_Suite*, const XML_Char*);
typedef XML_Bool (*SetDeferralFunction)(XML_Parser, XML_Bool);

static void DisableReparseDeferral(XML_Parser parser)
{
  static SetDeferralFunction setDeferral = NULL;
  static int looked = 0;
  if (!looked)
  {
    setDeferral = (SetDeferralFunction)dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled");
    looked = 1;
  }
  if (parser && setDeferral)
  {
    setDeferral(parser, XML_FALSE);
  }
}

XML_Parser XML_ParserCreate(const XML_Char* encoding)
{
  CreateFunction create = (CreateFunction)dlsym(RTLD_NEXT, "XML_ParserCreate");
  XML_Parser parser = create ? create(encoding) : NULL;
  DisableReparseDeferral(parser);
  return parser;
}

XML_Parser XML_ParserCreateNS(const XML_Char* encoding, XML_Char separator)
{
  CreateNSFunction create = (CreateNSFunction)dlsym(RTLD_NEXT, "XML_ParserCreateNS");
  XML_Parser parser = create ? create(encoding, separator) : NULL;
  DisableReparseDeferral(parser);
  return parser;
}

XML_Parser XML_ParserCreate_MM(
  const XML_Char* encoding, const XML_Memory_Handling_Suite* memory, const XML_Char* separator)
{
  CreateMMFunction create = (CreateMMFunction)dlsym(RTLD_NEXT, "XML_ParserCreate_MM");
  XML_Parser parser = create ? create(encoding, memory, separator) : NULL;
  DisableReparseDeferral(parser);
  return parser;
}
