// Every option of a scene, declared: the lists ReadScene reads, in its order.
#include "vibrotherm/contact/contact_parameter_list.hpp"
#include "vibrotherm/coupling/continuation/periodic_options.hpp"
#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/heat/heat_boundary.hpp"

namespace vibrotherm::coupling {

void AddSceneOptions(OptionRegistry* registry) {
  registry->Add(DriverOptionSpecs())
      .Add(wave::ElasticMaterialOptionSpecs())
      .Add(wave::ExcitationOptionSpecs())
      .Add(wave::MaterialDampingOptionSpecs())
      .Add(wave::WaveOptionSpecs());
  std::vector<contact::ParameterSpec> contact;  // -contact_a0 is vibrotherm-contact's, refused here
  for (const contact::ContactParameter& p : contact::contact_parameters())
    if (p.spec.name != "-contact_a0") contact.push_back(p.spec);
  registry->Add(contact)
      .Add(interface::ApproachProfileOptionSpecs())
      .Add(heat::HeatMaterialOptionSpecs())
      .Add(heat::HeatDiscretisationOptionSpecs())
      .Add(heat::HeatBoundaryOptionSpecs())
      .Add(CameraOptionSpecs())
      .Add(PeriodicOptionSpecs())
      .Add(mesh::MeshSourceOptionSpecs())
      .Add(mesh::SpecimenGeometryOptionSpecs())
      .Add(mesh::HeatMeshOptionSpecs());
}

}  // namespace vibrotherm::coupling
