/*
 * fake_reparse_deferral: a test library that makes a process look as if its libexpat deferred
 * re-parsing (Debian 12's 2.5.0-1+deb12u2 and later), on a machine whose libexpat does not.
 *
 * Preloaded (LD_PRELOAD), it exports XML_SetReparseDeferralEnabled, the function the DGMF plugin
 * looks for (Plugin/DGMFExpatCheck.h). It forwards to the real function when the real libexpat
 * has one, so on a machine with a deferring libexpat it changes nothing. Test use only.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <expat.h>

typedef XML_Bool (*SetDeferralFunction)(XML_Parser, XML_Bool);

XML_Bool XML_SetReparseDeferralEnabled(XML_Parser parser, XML_Bool enabled)
{
  SetDeferralFunction real = (SetDeferralFunction)dlsym(RTLD_NEXT, "XML_SetReparseDeferralEnabled");
  return real ? real(parser, enabled) : XML_FALSE;
}
