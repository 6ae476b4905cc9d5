# plume_encode_shaders(<sources-var> <headers-var> <file.glsl>...)
#
# Turns each .glsl file into a C string (vtk_encode_string) and returns the
# generated sources and headers for vtk_module_add_module. Modules include
# this file by a path relative to themselves, so it works in the standalone
# driver, as a VTK remote module and in ParaView's plugin build (where
# vtk_encode_string already exists, hence the guard).
include_guard(GLOBAL)
if (NOT COMMAND vtk_encode_string)
  include(vtkEncodeString)
endif ()

function (plume_encode_shaders sources_var headers_var)
  set(sources)
  set(headers)
  foreach (shader_file IN LISTS ARGN)
    vtk_encode_string(
      INPUT         "${shader_file}"
      HEADER_OUTPUT header
      SOURCE_OUTPUT source)
    list(APPEND sources "${source}")
    list(APPEND headers "${header}")
  endforeach ()
  set("${sources_var}" "${sources}" PARENT_SCOPE)
  set("${headers_var}" "${headers}" PARENT_SCOPE)
endfunction ()
