/**
 * @class   vtkPlumeShaderVariants
 * @brief   picks the shader variant a scene needs out of a .glsl template
 *
 * Plume's .glsl files hold every feature of a renderer; blocks between
 * `//PLUME::IF term1 term2 ...` and `//PLUME::ENDIF` are kept only when one
 * of their terms holds (OR), a term `A+B` holding when all its names are
 * enabled (AND); blocks nest (an inner block is kept only inside a kept
 * outer one). The `//PLUME::Defines` tag is replaced by the given #define
 * lines. So only the features in use are compiled, and each variant can be
 * cached by its feature set (vtkPlumeShaderFeatures,
 * vtkPlumeShaderProgramCache).
 */
#ifndef vtkPlumeShaderVariants_h
#define vtkPlumeShaderVariants_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkWrappingHints.h"     // For VTK_WRAPEXCLUDE

#include <set>    // For std::set
#include <string> // For std::string

class PLUMERENDERINGCORE_EXPORT VTK_WRAPEXCLUDE vtkPlumeShaderVariants
{
public:
  /** The source with the disabled blocks removed and the defines inserted. */
  static std::string Select(
    const char* source, const std::set<std::string>& enabled, const std::string& defines);
};

#endif
