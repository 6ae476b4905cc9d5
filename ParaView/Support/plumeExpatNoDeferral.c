/*
 * LD_PRELOAD shim: every expat parser is created with reparse deferral off.
 *
 * Why: Debian 12's expat 2.5.0-1+deb12u2 backports the fix for CVE-2023-52425
 * (expat 2.6.0's "reparse deferral": a start tag split over two XML_Parse
 * calls is reported only once more input arrives). VTK 9.2, which ParaView
 * 5.11 bundles, feeds its XML readers incrementally and stops at
 * <AppendedData> before the raw bytes; with deferral the tag is reported late,
 * expat parses the binary data and fails ("not well-formed (invalid token)").
 * That breaks every XML file with raw appended data, and RedistributeDataSet,
 * whose transfers between ranks are such files. VTK later disabled deferral
 * itself (VTK issue 19258). This shim does the same from outside: it wraps the
 * parser constructors and XML_ParserReset (which re-enables deferral).
 *
 * Use: LD_PRELOAD=<build>/lib/libplumeExpatNoDeferral.so pvbatch ...
 * (scripts/test-paraview.sh sets it for every test).
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <expat.h>

static void NoDeferral(XML_Parser parser)
{
  if (parser)
  {
    XML_SetReparseDeferralEnabled(parser, XML_FALSE);
  }
}

XML_Parser XML_ParserCreate(const XML_Char* encoding)
{
  static XML_Parser (*real)(const XML_Char*) = 0;
  if (!real)
  {
    *(void**)(&real) = dlsym(RTLD_NEXT, "XML_ParserCreate");
  }
  XML_Parser parser = real(encoding);
  NoDeferral(parser);
  return parser;
}

XML_Parser XML_ParserCreateNS(const XML_Char* encoding, XML_Char separator)
{
  static XML_Parser (*real)(const XML_Char*, XML_Char) = 0;
  if (!real)
  {
    *(void**)(&real) = dlsym(RTLD_NEXT, "XML_ParserCreateNS");
  }
  XML_Parser parser = real(encoding, separator);
  NoDeferral(parser);
  return parser;
}

XML_Parser XML_ParserCreate_MM(
  const XML_Char* encoding, const XML_Memory_Handling_Suite* memsuite, const XML_Char* separator)
{
  static XML_Parser (*real)(const XML_Char*, const XML_Memory_Handling_Suite*, const XML_Char*) = 0;
  if (!real)
  {
    *(void**)(&real) = dlsym(RTLD_NEXT, "XML_ParserCreate_MM");
  }
  XML_Parser parser = real(encoding, memsuite, separator);
  NoDeferral(parser);
  return parser;
}

XML_Bool XML_ParserReset(XML_Parser parser, const XML_Char* encoding)
{
  static XML_Bool (*real)(XML_Parser, const XML_Char*) = 0;
  if (!real)
  {
    *(void**)(&real) = dlsym(RTLD_NEXT, "XML_ParserReset");
  }
  XML_Bool ok = real(parser, encoding);
  NoDeferral(parser);
  return ok;
}
