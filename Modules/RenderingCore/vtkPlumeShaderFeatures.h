/**
 * @class   vtkPlumeShaderFeatures
 * @brief   the typed feature set of one shader variant: blocks kept, #defines, and the cache key
 *
 * A renderer says which features of its .glsl templates a frame needs
 * (Enable) and which constants the shaders take as #defines (Define); the
 * set yields the variant's sources (vtkPlumeShaderVariants keeps the
 * `//PLUME::IF` blocks of the enabled features and inserts the defines at
 * `//PLUME::Defines`) and the key vtkPlumeShaderProgramCache caches the
 * program under. Each enabled feature NAME is also defined as
 * `PLUME_FEATURE_NAME 1`, so shaders may use the preprocessor's nestable
 * `#if defined(PLUME_FEATURE_A) && !defined(PLUME_FEATURE_B)` as well.
 * Building keys by hand from strings (and forgetting a feature in the key)
 * is what this replaces.
 */
#ifndef vtkPlumeShaderFeatures_h
#define vtkPlumeShaderFeatures_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkWrappingHints.h"         // For VTK_WRAPEXCLUDE

#include <map>    // For std::map
#include <set>    // For std::set
#include <string> // For std::string

class PLUMERENDERINGCORE_EXPORT VTK_WRAPEXCLUDE vtkPlumeShaderFeatures
{
public:
  /** Keep the `//PLUME::IF` blocks that name `feature` (when `on`). Names: [A-Za-z0-9_]. */
  vtkPlumeShaderFeatures& Enable(const std::string& feature, bool on = true);
  /** `#define name value` in every stage's `//PLUME::Defines`. */
  vtkPlumeShaderFeatures& Define(const std::string& name, const std::string& value);
  vtkPlumeShaderFeatures& Define(const std::string& name, long long value);

  bool IsEnabled(const std::string& feature) const { return this->Enabled.count(feature) > 0; }
  const std::set<std::string>& GetEnabled() const { return this->Enabled; }
  /** The #define lines: the defines, then PLUME_FEATURE_<name> for each enabled feature. */
  std::string GetDefines() const;
  /** Equal keys exactly when the selected sources are equal. */
  std::string GetKey() const;

private:
  std::set<std::string> Enabled;
  std::map<std::string, std::string> Defines;
};

#endif
// VTK-HeaderTest-Exclude: vtkPlumeShaderFeatures.h
