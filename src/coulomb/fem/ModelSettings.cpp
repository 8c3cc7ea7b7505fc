#include "coulomb/fem/ModelSettings.hpp"

#include <cmath>

#include <limits>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/Choices.hpp"
#include "coulomb/io/ParameterValidation.hpp"
#include "coulomb/io/RangeValidator.hpp"

namespace coulomb::fem {

using Teuchos::Array;
using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

namespace {

// The deck's enumerations of the model, each declared once (io::Choices).
const io::Choices<MaterialModel> kMaterialModels{{"Linear Elastic", MaterialModel::LinearElastic},
                                                 {"Neo-Hookean", MaterialModel::NeoHookean}};
const io::Choices<PlaneAssumption> kPlaneAssumptions{{"Plane Strain", PlaneAssumption::PlaneStrain},
                                                     {"Plane Stress", PlaneAssumption::PlaneStress},
                                                     {"Axisymmetric", PlaneAssumption::Axisymmetric}};
/// A Dirichlet condition's component; -1: all of them.
const io::Choices<int> kComponents{{"x", 0}, {"y", 1}, {"z", 2}, {"all", -1}};
const io::Choices<NeumannCondition::Kind> kLoadTypes{{"Pressure", NeumannCondition::Kind::Pressure},
                                                     {"Traction", NeumannCondition::Kind::Traction}};

const char* const kFunctionDoc =
    "name of a sublist of 'Functions', or 'ramp' (f = t) or 'constant' (f = 1)";

TimeFunction lookupFunction(const ParameterList& deck, const std::string& name, const std::string& where) {
  if (name == "ramp") return TimeFunction::ramp();
  if (name == "constant") return TimeFunction::constant();
  const bool known = deck.isSublist("Functions") && deck.sublist("Functions").isSublist(name);
  COULOMB_REQUIRE(known, "deck: '" << where << "/Function' names '" << name
                                   << "', which is neither 'ramp', 'constant' nor a sublist of 'Functions'");
  const ParameterList& f = deck.sublist("Functions").sublist(name);
  const std::string path = "Functions/" + name;
  const auto times = f.get<Array<double>>("Times");
  const auto values = f.get<Array<double>>("Values");
  return TimeFunction(times.toVector(), values.toVector(), path);
}

std::array<double, 3> vectorOfDimension(const Array<double>& a, int dimension, const std::string& where) {
  COULOMB_REQUIRE(static_cast<int>(a.size()) == dimension,
                  "deck: '" << where << "' needs " << dimension << " components (mesh dimension), got " << a.size());
  std::array<double, 3> v{};
  for (int i = 0; i < dimension; ++i) v[i] = a[i];
  return v;
}

}  // namespace

void addValidModelParameters(ParameterList& valid) {
  ParameterList& materials = valid.sublist("Materials", false, "One sublist per material, named freely");
  ParameterList& material = materials.sublist("*", false, "a material");
  material.set("Model", std::string(kMaterialModels.name(MaterialModel::LinearElastic)),
               "small-strain linear elasticity, or compressible Neo-Hookean (total Lagrangian)",
               kMaterialModels.validator());
  material.set("Young's Modulus", 1.0, std::string(io::kRequired) + "E [force/area]", io::positive());
  material.set("Poisson's Ratio", 0.0, std::string(io::kRequired) + "nu", rcp(new io::RangeValidator(-1.0, true, 0.5, true)));

  ParameterList& blocks = valid.sublist("Element Blocks", false, "One sublist per mesh element block, named as in the mesh");
  ParameterList& block = blocks.sublist("*", false, "an element block");
  block.set("Material", "", std::string(io::kRequired) + "name of a sublist of 'Materials'");
  block.set("Thickness", 1.0, "out-of-plane thickness of 2D blocks [length]", io::positive());

  ParameterList& problem = valid.sublist("Problem", false, "Modelling assumptions");
  problem.set("Plane Assumption", std::string(kPlaneAssumptions.name(PlaneAssumption::PlaneStrain)),
              "2D meshes: plane strain, plane stress, or axisymmetric (x = radius >= 0, y = axis; forces and "
              "reactions of the whole ring, stress_zz = hoop stress)",
              kPlaneAssumptions.validator());

  ParameterList& functions = valid.sublist("Functions", false, "Piecewise-linear functions of pseudo time, named freely");
  ParameterList& function = functions.sublist("*", false, "a function");
  function.set("Times", Array<double>(), std::string(io::kRequired) + "strictly increasing times");
  function.set("Values", Array<double>(), std::string(io::kRequired) + "values at those times");

  ParameterList& dirichlet = valid.sublist("Dirichlet Conditions", false, "Prescribed displacements, named freely");
  ParameterList& d = dirichlet.sublist("*", false, "u_c = (Value + Linear Coefficients . X) f(t) on a node set");
  d.set("Node Set", "", std::string(io::kRequired) + "node set name (or nodeset_<id>)");
  d.set("Component", std::string(kComponents.name(-1)), "displaced component", kComponents.validator());
  d.set("Value", 0.0, "constant part of the prescribed displacement [length]");
  d.set("Linear Coefficients", Array<double>(), "optional gradient: adds c . X (one entry per dimension)");
  d.set("Function", "ramp", kFunctionDoc);
  d.set("Rotation Angle", 0.0,
        "rigid rotation [rad] of the node set, times Function: carries the displacements prescribed on these nodes by "
        "the conditions listed before (Component all; no Value or Linear Coefficients)");
  d.set("Rotation Center", Array<double>(), "centre of the rotation (one entry per dimension; default the origin)");
  d.set("Rotation Axis", Array<double>(), "3D: axis of the rotation (default z)");

  ParameterList& neumann = valid.sublist("Neumann Conditions", false, "Surface loads on side sets, named freely");
  ParameterList& n = neumann.sublist("*", false, "a dead load on the reference surface");
  n.set("Side Set", "", std::string(io::kRequired) + "side set name (or sideset_<id>)");
  n.set("Type", "Pressure", "Pressure (> 0 pushes into the body) or Traction (vector)", kLoadTypes.validator());
  n.set("Value", 0.0, "pressure [force/area] (Type = Pressure)");
  n.set("Traction", Array<double>(), "traction vector [force/area] (Type = Traction)");
  n.set("Function", "ramp", kFunctionDoc);

  ParameterList& bodyForces = valid.sublist("Body Forces", false, "Forces per reference volume, named freely");
  ParameterList& b = bodyForces.sublist("*", false, "a body force");
  b.set("Block", "", "element block name; empty = all blocks");
  b.set("Force", Array<double>(), std::string(io::kRequired) + "force per volume, one entry per dimension");
  b.set("Function", "ramp", kFunctionDoc);
}

ModelSettings parseModelSettings(const ParameterList& deck, int dimension) {
  ParameterList valid;
  addValidModelParameters(valid);
  ModelSettings model;
  const ParameterList empty;
  const ParameterList& problem = deck.isSublist("Problem") ? deck.sublist("Problem") : empty;
  const PlaneAssumption plane =
      kPlaneAssumptions.value(io::valueOrDefault<std::string>(problem, valid.sublist("Problem"), "Plane Assumption"));
  // A 2D deck on a 3D mesh would run, with what the user gave ignored.
  COULOMB_REQUIRE(dimension == 2 || !problem.isParameter("Plane Assumption"),
                  "deck: 'Problem/Plane Assumption' is for 2D meshes, but the mesh is 3D");

  const ParameterList& materials = deck.isSublist("Materials") ? deck.sublist("Materials") : empty;
  const ParameterList& validMaterial = valid.sublist("Materials").sublist("*");
  const ParameterList& blocks = deck.isSublist("Element Blocks") ? deck.sublist("Element Blocks") : empty;
  const ParameterList& validBlock = valid.sublist("Element Blocks").sublist("*");
  for (auto it = blocks.begin(); it != blocks.end(); ++it) {
    const std::string& blockName = blocks.name(it);
    const ParameterList& block = blocks.sublist(blockName);
    const std::string materialName = block.get<std::string>("Material");
    COULOMB_REQUIRE(materials.isSublist(materialName), "deck: 'Element Blocks/" << blockName << "/Material' names '"
                                                                                << materialName << "', which is not a sublist of 'Materials'");
    const ParameterList& m = materials.sublist(materialName);
    const std::string where = "Materials/" + materialName;
    MaterialParameters p;
    p.model = kMaterialModels.value(io::valueOrDefault<std::string>(m, validMaterial, "Model"));
    p.youngsModulus = m.get<double>("Young's Modulus");
    p.poissonRatio = m.get<double>("Poisson's Ratio");
    p.plane = plane;
    COULOMB_REQUIRE(!(dimension == 2 && p.plane == PlaneAssumption::PlaneStress && p.model == MaterialModel::NeoHookean),
                    "deck: '" << where << "' is Neo-Hookean, which supports 'Problem/Plane Assumption' = 'Plane Strain' "
                                 "or 'Axisymmetric', not 'Plane Stress'");
    COULOMB_REQUIRE(!(dimension == 2 && p.plane == PlaneAssumption::Axisymmetric && block.isParameter("Thickness")),
                    "deck: 'Element Blocks/" << blockName << "/Thickness' has no meaning with 'Problem/Plane Assumption' "
                                                            "= 'Axisymmetric' (the ring is whole)");
    COULOMB_REQUIRE(dimension == 2 || !block.isParameter("Thickness"),
                    "deck: 'Element Blocks/" << blockName << "/Thickness' is for 2D meshes, but the mesh is 3D");
    p.thickness = io::valueOrDefault<double>(block, validBlock, "Thickness");
    model.blockMaterials[blockName] = p;
  }

  const ParameterList& dirichlet = deck.isSublist("Dirichlet Conditions") ? deck.sublist("Dirichlet Conditions") : empty;
  const ParameterList& validD = valid.sublist("Dirichlet Conditions").sublist("*");
  for (auto it = dirichlet.begin(); it != dirichlet.end(); ++it) {
    const std::string& name = dirichlet.name(it);
    const ParameterList& d = dirichlet.sublist(name);
    const std::string where = "Dirichlet Conditions/" + name;
    DirichletCondition c;
    c.name = name;
    c.nodeSet = d.get<std::string>("Node Set");
    const int component = kComponents.value(io::valueOrDefault<std::string>(d, validD, "Component"));
    if (component < 0) {
      for (int i = 0; i < dimension; ++i) c.components.push_back(i);
    } else {
      COULOMB_REQUIRE(component < dimension, "deck: '" << where << "/Component' is 'z' but the mesh is 2D");
      c.components.push_back(component);
    }
    c.value = io::valueOrDefault<double>(d, validD, "Value");
    if (d.isParameter("Linear Coefficients")) {
      const auto coefficients = vectorOfDimension(d.get<Array<double>>("Linear Coefficients"), dimension,
                                                  where + "/Linear Coefficients");
      c.linearCoefficients.assign(coefficients.begin(), coefficients.begin() + dimension);
    }
    c.function = lookupFunction(deck, io::valueOrDefault<std::string>(d, validD, "Function"), where);
    c.rotationAngle = io::valueOrDefault<double>(d, validD, "Rotation Angle");
    // A given angle, even 0, makes a rotation: read as a plain condition,
    // `Rotation Angle` 0 would fix the node set (Value 0, all components).
    c.rotation = d.isParameter("Rotation Angle");
    if (c.rotation) {
      COULOMB_REQUIRE(component < 0, "deck: '" << where << "/Rotation Angle' needs 'Component' = 'all'");
      COULOMB_REQUIRE(!d.isParameter("Value") && !d.isParameter("Linear Coefficients"),
                      "deck: '" << where << "/Rotation Angle' rotates the displacements of the conditions before it: "
                                << "give no 'Value' or 'Linear Coefficients' with it");
      if (d.isParameter("Rotation Center")) {
        const auto center = vectorOfDimension(d.get<Array<double>>("Rotation Center"), dimension, where + "/Rotation Center");
        for (int i = 0; i < dimension; ++i) c.rotationCenter[i] = center[i];
      }
      if (d.isParameter("Rotation Axis")) {
        COULOMB_REQUIRE(dimension == 3, "deck: '" << where << "/Rotation Axis' is for 3D meshes (2D rotates about z)");
        const auto axis = vectorOfDimension(d.get<Array<double>>("Rotation Axis"), 3, where + "/Rotation Axis");
        const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        COULOMB_REQUIRE(norm > 0.0, "deck: '" << where << "/Rotation Axis' must not be zero");
        for (int i = 0; i < 3; ++i) c.rotationAxis[i] = axis[i] / norm;
      }
    }
    model.dirichlet.push_back(std::move(c));
  }

  const ParameterList& neumann = deck.isSublist("Neumann Conditions") ? deck.sublist("Neumann Conditions") : empty;
  const ParameterList& validN = valid.sublist("Neumann Conditions").sublist("*");
  for (auto it = neumann.begin(); it != neumann.end(); ++it) {
    const std::string& name = neumann.name(it);
    const ParameterList& n = neumann.sublist(name);
    const std::string where = "Neumann Conditions/" + name;
    NeumannCondition c;
    c.name = name;
    c.sideSet = n.get<std::string>("Side Set");
    c.kind = kLoadTypes.value(io::valueOrDefault<std::string>(n, validN, "Type"));
    const bool isPressure = c.kind == NeumannCondition::Kind::Pressure;
    if (isPressure) {
      COULOMB_REQUIRE(!n.isParameter("Traction"), "deck: '" << where << "' is a Pressure but gives 'Traction'");
      c.pressure = io::valueOrDefault<double>(n, validN, "Value");
    } else {
      COULOMB_REQUIRE(n.isParameter("Traction"), "deck: '" << where << "' has Type Traction but no 'Traction' vector");
      COULOMB_REQUIRE(!n.isParameter("Value"), "deck: '" << where << "' is a Traction but gives a pressure 'Value'");
      c.traction = vectorOfDimension(n.get<Array<double>>("Traction"), dimension, where + "/Traction");
    }
    c.function = lookupFunction(deck, io::valueOrDefault<std::string>(n, validN, "Function"), where);
    model.neumann.push_back(std::move(c));
  }

  const ParameterList& bodyForces = deck.isSublist("Body Forces") ? deck.sublist("Body Forces") : empty;
  const ParameterList& validB = valid.sublist("Body Forces").sublist("*");
  for (auto it = bodyForces.begin(); it != bodyForces.end(); ++it) {
    const std::string& name = bodyForces.name(it);
    const ParameterList& b = bodyForces.sublist(name);
    const std::string where = "Body Forces/" + name;
    BodyForce f;
    f.name = name;
    const std::string block = io::valueOrDefault<std::string>(b, validB, "Block");
    if (!block.empty()) f.block = block;
    f.force = vectorOfDimension(b.get<Array<double>>("Force"), dimension, where + "/Force");
    f.function = lookupFunction(deck, io::valueOrDefault<std::string>(b, validB, "Function"), where);
    model.bodyForces.push_back(std::move(f));
  }
  return model;
}

}  // namespace coulomb::fem
