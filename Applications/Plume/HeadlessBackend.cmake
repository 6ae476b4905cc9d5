# SPDX-License-Identifier: BSD-3-Clause
#
# plume_add_headless_backend(<target>)
#
# Adds the render-window factory (plume::CreateRenderWindow, backends
# auto|osmesa|x) to an executable target:
#   - sources plumeRenderWindowFactory.cxx and plumeGLXShim.cxx;
#   - OSMesa (pkg-config "osmesa", else find_library(OSMesa)); when found,
#     PLUME_HAVE_OSMESA is defined and libOSMesa is put FIRST on the link line
#     (as a link option, so it precedes the objects and every library whatever
#     the order of target_link_libraries calls): VTK's direct GL 1.x calls must
#     bind to libOSMesa, not to libGL/libOpenGL;
#   - ENABLE_EXPORTS (-rdynamic) so the executable's glX* stand-ins interpose
#     libGL's for GLEW; libdl;
#   - Xlib (PLUME_HAVE_XLIB) to probe $DISPLAY before VTK's X window, which
#     abort()s on a bad connection.
# Without OSMesa the build still succeeds; `--backend osmesa` then reports a
# clear error and `auto` uses X.
#
# The target must also link VTK::RenderingOpenGL2 (and VTK::CommonCore).
# Only executables: the stand-ins must be exported by the main program.

include_guard(GLOBAL)


function(plume_add_headless_backend target)
  set(_plume_headless_dir "${CMAKE_CURRENT_FUNCTION_LIST_DIR}")
  get_target_property(_type ${target} TYPE)
  if (NOT _type STREQUAL "EXECUTABLE")
    message(FATAL_ERROR "plume_add_headless_backend(${target}): target must be an executable")
  endif ()

  target_sources(${target} PRIVATE
    "${_plume_headless_dir}/plumeRenderWindowFactory.cxx"
    "${_plume_headless_dir}/plumeRenderWindowFactory.h"
    "${_plume_headless_dir}/plumeGLXShim.cxx"
    "${_plume_headless_dir}/plumeGLXShim.h")
  target_include_directories(${target} PRIVATE "${_plume_headless_dir}")

  # --- OSMesa ---------------------------------------------------------------
  if (NOT DEFINED PLUME_OSMESA_LIBRARY OR NOT DEFINED PLUME_OSMESA_INCLUDE_DIR)
    find_package(PkgConfig QUIET)
    set(_hints_lib)
    set(_hints_inc)
    if (PkgConfig_FOUND)
      pkg_check_modules(PC_PLUME_OSMESA QUIET osmesa)
      set(_hints_lib ${PC_PLUME_OSMESA_LIBRARY_DIRS})
      set(_hints_inc ${PC_PLUME_OSMESA_INCLUDE_DIRS})
    endif ()
    find_library(PLUME_OSMESA_LIBRARY NAMES OSMesa OSMesa32 HINTS ${_hints_lib})
    find_path(PLUME_OSMESA_INCLUDE_DIR NAMES GL/osmesa.h HINTS ${_hints_inc})
  endif ()
  option(PLUME_ENABLE_OSMESA "Build the in-process OSMesa render backend if OSMesa is found" ON)

  if (PLUME_ENABLE_OSMESA AND PLUME_OSMESA_LIBRARY AND PLUME_OSMESA_INCLUDE_DIR)
    message(STATUS "plume ${target}: OSMesa backend enabled (${PLUME_OSMESA_LIBRARY})")
    target_compile_definitions(${target} PRIVATE PLUME_HAVE_OSMESA=1)
    target_include_directories(${target} PRIVATE "${PLUME_OSMESA_INCLUDE_DIR}")
    # Link option (not target_link_libraries): lands before the objects and all
    # libraries, so libOSMesa is the executable's first DT_NEEDED and wins the
    # global lookup of gl* symbols over libGL/libOpenGL. SHELL: keeps the group
    # from being de-duplicated/reordered; --no-as-needed keeps it although no
    # object precedes it.
    target_link_options(${target} PRIVATE
      "SHELL:-Wl,--push-state,--no-as-needed \"${PLUME_OSMESA_LIBRARY}\" -Wl,--pop-state")
  elseif (NOT PLUME_ENABLE_OSMESA)
    message(STATUS "plume ${target}: OSMesa backend disabled (PLUME_ENABLE_OSMESA=OFF); only the X backend is built")
  else ()
    message(STATUS "plume ${target}: OSMesa not found (libosmesa6-dev); only the X backend is built")
  endif ()

  # --- Xlib (display probe) -------------------------------------------------
  find_package(X11 QUIET)
  if (X11_FOUND)
    target_compile_definitions(${target} PRIVATE PLUME_HAVE_XLIB=1)
    target_link_libraries(${target} PRIVATE X11::X11)
  endif ()

  set_target_properties(${target} PROPERTIES ENABLE_EXPORTS ON)
  target_link_libraries(${target} PRIVATE ${CMAKE_DL_LIBS})
endfunction()
