// The contact models a scene can name (parameter contact/model), each built
// once per moving part and its fixed parts (docs/design.md decision 7). A new
// contact model is one entry of the table in contact_registry.cc: a name, a
// one-line description for the parameter table, a builder, the parameters it
// declares beyond ContactParams' shared ones, and whether it builds rims.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "vahf/contact/contact_model.h"
#include "vahf/contact/contact_params.h"
#include "vahf/core/param_decl.h"
#include "vahf/geometry/shape.h"

namespace vahf::contact {

// A part as contact sees it: its shape (in its own frame), where it stands
// (fixed parts only), its Coulomb coefficient and the radius of a sphere about
// its frame origin holding it.
struct ContactBody {
  const geometry::Shape* shape = nullptr;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double friction = 0;
  double bounding_radius = 0;
};

// What a builder gets: the moving part, the fixed parts it can touch (at
// least one), the scene's contact parameters (its declared keys' values in
// params.values) and the figures a stiffness rule may use.
struct ContactSetup {
  ContactBody moving;
  std::vector<ContactBody> fixed;
  ContactParams params;
  double penetration_bound = 0;  // m; 0: the scene has no radial fit to bound
  double steady_load = 0;        // N: the largest steady load on the part
  double clearance = 0;          // m: the smallest radial clearance; 0: no fit
};

// A built model and the stiffnesses it chose (what a trial records).
struct BuiltContact {
  std::shared_ptr<const ContactModel> model;
  double stiffness = 0;       // Pa/m, the face law's
  double line_stiffness = 0;  // Pa, the rim law's; 0: no rims
  double barrier_depth = 0;   // m, the hardening barrier's b; 0: no barrier
  std::int64_t shell_points = 0;
};

struct ContactModelEntry {
  const char* name;
  const char* description;  // one line, for vahf params
  BuiltContact (*build)(const ContactSetup& setup);
  // The keys it reads from ContactParams::values, each declared once beside
  // the code that reads it; the parameter table lists every entry's keys
  // under contact/, and a scene may set them whatever its model.
  std::vector<const core::ParamDecl*> params = {};
  // Whether it samples the parts' convex edges (rim.h): the scene loader
  // bounds the rims' size (rim_spacing) only for such a model.
  bool uses_rims = false;
};

// Every contact model, in the order vahf params lists them.
const std::vector<ContactModelEntry>& ContactModels();
std::vector<std::string> ContactModelNames();
// The model `name` (one of ContactModelNames: the parameter table checked it).
const ContactModelEntry& FindContactModel(const std::string& name);
// Every entry's declared parameter once, in the order of the entries and of
// their lists. A key is declared by one object, however many entries read it.
const std::vector<const core::ParamDecl*>& ContactModelParams();

// The model `name` (one of ContactModelNames: the parameter table checked it).
BuiltContact BuildContact(const std::string& name, const ContactSetup& setup);

}  // namespace vahf::contact
