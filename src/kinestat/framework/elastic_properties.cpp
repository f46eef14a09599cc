// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/elastic_properties.hpp"

#include <algorithm>
#include <numbers>

#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

double shear_modulus(const Material& material) {
  if (material.shear_modulus) return *material.shear_modulus;
  if (material.poisson) return material.youngs_modulus / (2.0 * (1.0 + *material.poisson));
  return 0.0;
}

double rectangle_torsion_constant(double width, double thickness) {
  const double a = std::max(width, thickness), b = std::min(width, thickness);
  const double ratio = b / a;
  return a * b * b * b * (1.0 / 3.0 - 0.21 * ratio * (1.0 - ratio * ratio * ratio * ratio / 12.0));
}

Section completed_section(Section section) {
  switch (section.shape) {
    case SectionShape::circle: {
      const double d = section.dimensions[0], d2 = d * d;
      section.area = std::numbers::pi * d2 / 4.0;
      section.iy = section.iz = std::numbers::pi * d2 * d2 / 64.0;
      section.torsion = std::numbers::pi * d2 * d2 / 32.0;
      break;
    }
    case SectionShape::rectangle: {
      const double w = section.dimensions[0], t = section.dimensions[1];
      section.area = w * t;
      section.iy = w * t * t * t / 12.0;
      section.iz = t * w * w * w / 12.0;
      section.torsion = rectangle_torsion_constant(w, t);
      break;
    }
    case SectionShape::area_only: section.iy = section.iz = section.torsion = 0.0; break;
    case SectionShape::explicit_values:
    case SectionShape::rigidities: break;
  }
  return section;
}

const Material* element_material(const FrameworkModel& model, const Element& element) {
  const std::optional<std::size_t> index = element.material ? element.material : model.default_material;
  return index ? &model.materials[*index] : nullptr;
}

const Section* element_section(const FrameworkModel& model, const Element& element) {
  const std::optional<std::size_t> index = element.section ? element.section : model.default_section;
  return index ? &model.sections[*index] : nullptr;
}

}  // namespace kinestat::framework
