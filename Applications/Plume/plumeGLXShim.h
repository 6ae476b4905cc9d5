// SPDX-License-Identifier: BSD-3-Clause
// Control interface of the glX* stand-ins exported by the plume executable
// (see plumeGLXShim.cxx for why they exist).
#ifndef plumeGLXShim_h
#define plumeGLXShim_h

#include <string>

namespace plume
{
namespace glxshim
{
/// Route the glX* stand-ins to OSMesa (true) or to the real libGL/libGLX (false).
/// Set by the OSMesa render window while its context is current.
void SetOSMesaActive(bool active);
bool IsOSMesaActive();

/// True when the stand-ins are compiled in (PLUME_HAVE_OSMESA) AND they really
/// interpose the system glX* functions, i.e. the executable exports them
/// (ENABLE_EXPORTS / -rdynamic). On false, `why` says what is missing.
bool IsInstalled(std::string* why);
}
}

#endif
