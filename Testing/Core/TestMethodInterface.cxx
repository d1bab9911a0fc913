// The one method interface (DeformationMethod), the method table, and the core's checks of a
// problem: every method through the interface gives the bits of its own function, DGMF keeps r and
// f between motions, and bad problems get the messages the filter shows.
#include "SyntheticNodes.h"

#include "dgmf/DGMDeformation.h"
#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingField.h"
#include "dgmf/DeformationMethod.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/IDWDeformation.h"
#include "dgmf/Methods.h"
#include "dgmf/MultiBodyDeformation.h"
#include "dgmf/ResultNames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
dgmf::DeformationProblem ProblemOf(const dgmf_test::NodeSet& set, const dgmf::RigidMotion& motion)
{
  dgmf::DeformationProblem problem;
  problem.Dimension = set.Dimension;
  problem.NumberOfNodes = set.Size();
  problem.Points = set.Points.data();
  problem.Kinds = set.Kinds.data();
  problem.Motions = { motion };
  return problem;
}

dgmf::RigidMotion Rotation(double degrees)
{
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = degrees;
  motion.Translation[0] = 0.1;
  return motion;
}

/// A FieldStore that counts the fields it is asked to store (to see what DGMF recomputes).
class CountingStore : public dgmf::VectorFieldStore
{
public:
  using dgmf::VectorFieldStore::VectorFieldStore;
  double* Store(const char* field, const dgmf::FieldKey& key) override
  {
    this->Stored.push_back(field);
    return this->VectorFieldStore::Store(field, key);
  }
  std::vector<std::string> Stored;
};

/// Expects `call` to throw std::invalid_argument whose message contains `text`.
template <typename Call>
void ExpectRejected(const Call& call, const std::string& text)
{
  try
  {
    call();
    ADD_FAILURE() << "no exception; expected one saying: " << text;
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

bool SameBits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
} // namespace

TEST(MethodTable, NamesKeysAndValuesAreOneConsistentTable)
{
  const std::vector<dgmf::MethodInfo>& methods = dgmf::GetMethods();
  ASSERT_EQ(methods.size(), 5u);
  std::set<std::string> names, keys;
  for (std::size_t k = 0; k < methods.size(); ++k)
  {
    EXPECT_EQ(static_cast<int>(methods[k].Id), static_cast<int>(k)); // the filter's values
    names.insert(methods[k].Name);
    keys.insert(methods[k].Key);
    EXPECT_EQ(dgmf::FindMethod(methods[k].Name), &methods[k]);
    EXPECT_EQ(dgmf::FindMethod(methods[k].Key), &methods[k]);
    EXPECT_EQ(dgmf::FindMethod(static_cast<int>(methods[k].Id)), &methods[k]);
    EXPECT_EQ(&dgmf::GetMethodInfo(methods[k].Id), &methods[k]);
  }
  EXPECT_EQ(names.size(), methods.size());
  EXPECT_EQ(keys.size(), methods.size());
  EXPECT_STREQ(dgmf::FindMethod("dGrBf")->Name, "DGRBF");
  EXPECT_EQ(dgmf::FindMethod("laplace"), nullptr);
  EXPECT_EQ(dgmf::FindMethod(99), nullptr);
  EXPECT_EQ(dgmf::ListMethodKeys(", "), "dgmf, dgm, dgrbf, rbf, idw");
  EXPECT_TRUE(dgmf::GetMethodInfo(dgmf::Method::DGM).UsesGraph);
  EXPECT_FALSE(dgmf::GetMethodInfo(dgmf::Method::IDW).UsesGraph);
}

TEST(MethodInterface, EachMethodSaysWhatItNeeds)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(16, 6, 50);
  dgmf::DeformationProblem problem = ProblemOf(set, Rotation(10));
  dgmf::MethodParameters parameters;
  const auto dgmf = dgmf::CreateMethod(dgmf::Method::DGMF, parameters);
  dgmf::MethodNeeds needs = dgmf->GetNeeds(problem);
  EXPECT_TRUE(needs.Graph && needs.R && needs.F);
  EXPECT_FALSE(needs.Cells || needs.BoundaryWeights);
  problem.ExtractRigidMotion = true; // several bodies: no single r
  needs = dgmf->GetNeeds(problem);
  EXPECT_TRUE(needs.F && !needs.R);
  parameters.SubSteps = 0;
  EXPECT_TRUE(dgmf::CreateMethod(dgmf::Method::DGMF, parameters)->GetNeeds(problem).Cells);
  const auto idw = dgmf::CreateMethod(dgmf::Method::IDW, dgmf::MethodParameters());
  needs = idw->GetNeeds(problem);
  EXPECT_TRUE(needs.BoundaryWeights && !needs.Graph && !needs.R && !needs.F);
  EXPECT_TRUE(
    dgmf::CreateMethod(dgmf::Method::DGM, dgmf::MethodParameters())->GetNeeds(problem).Graph);
  EXPECT_STREQ(idw->GetInfo().Name, "IDW");
}

TEST(MethodInterface, DGMFGivesTheBitsOfItsFunctionsAndKeepsRAndF)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(800);
  const dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  dgmf::MethodParameters parameters;
  parameters.StaticR0 = 1.5;
  // Direct: paper steps 4-7.
  std::vector<double> r(set.Size()), f(set.Size()), expected(set.Points.size());
  dgmf::ComputeBoundaryDistanceField(mapping, 1.5, r.data(), dgmf::SerialFor);
  dgmf::ComputeDampingFactor(
    mapping, dgmf::DampingFunction::U1, r.data(), f.data(), dgmf::SerialFor);
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[0] = 20;
  motion.AnglesDegrees[1] = -35;
  dgmf::DeformDGMF(mapping, f.data(), motion, nullptr, dgmf::DeformationMode::DGMF2,
    set.Points.data(), expected.data(), dgmf::SerialFor);
  // Through the interface.
  const auto method = dgmf::CreateMethod(dgmf::Method::DGMF, parameters);
  CountingStore store(set.Size());
  std::vector<double> deformed(set.Points.size());
  const dgmf::DeformationReport report = method->Deform(ProblemOf(set, motion), &mapping,
    dgmf::DeformationOutputs{ deformed.data(), &store }, dgmf::SerialFor);
  EXPECT_TRUE(SameBits(deformed, expected));
  EXPECT_TRUE(SameBits(store.Get(dgmf::names::R), r));
  EXPECT_TRUE(SameBits(store.Get(dgmf::names::F), f));
  ASSERT_EQ(report.Values.size(), 1u);
  EXPECT_EQ(report.Values[0].Name, dgmf::names::OutsideNodeCount);
  EXPECT_EQ(store.Stored.size(), 2u);
  // A new motion reuses r and f; a new damping function recomputes f only.
  motion.AnglesDegrees[2] = 5;
  method->Deform(ProblemOf(set, motion), &mapping,
    dgmf::DeformationOutputs{ deformed.data(), &store }, dgmf::SerialFor);
  EXPECT_EQ(store.Stored.size(), 2u);
  parameters.Damping = dgmf::DampingFunction::U2;
  dgmf::CreateMethod(dgmf::Method::DGMF, parameters)
    ->Deform(ProblemOf(set, motion), &mapping, dgmf::DeformationOutputs{ deformed.data(), &store },
      dgmf::SerialFor);
  ASSERT_EQ(store.Stored.size(), 3u);
  EXPECT_EQ(store.Stored[2], dgmf::names::F);
}

TEST(MethodInterface, SeveralBodiesGiveTheBitsOfDeformMultiBody)
{
  dgmf_test::NodeSet set = dgmf_test::CircleInSquare(32, 10, 600);
  std::vector<std::int32_t> ids(set.Size(), 0);
  for (std::size_t i = 0; i < 32; ++i)
  {
    ids[i] = set.Points[3 * i] < 0.0 ? 1 : 2; // the two halves of the circle
  }
  const dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  std::vector<dgmf::BodyMotion> bodies(2);
  bodies[0].Motion = Rotation(15);
  bodies[1].Motion = Rotation(-20);
  std::vector<double> expected(set.Points.size()), f(set.Size());
  dgmf::DeformMultiBody(mapping, ids.data(), bodies, 1.0, dgmf::DampingFunction::U1,
    dgmf::DeformationMode::DGMF2, set.Points.data(), expected.data(), f.data(), dgmf::SerialFor);
  dgmf::DeformationProblem problem = ProblemOf(set, bodies[0].Motion);
  problem.Motions.push_back(bodies[1].Motion);
  problem.BodyIds = ids.data();
  problem.NumberOfBodies = 2;
  dgmf::VectorFieldStore store(set.Size());
  std::vector<double> deformed(set.Points.size());
  dgmf::CreateMethod(dgmf::Method::DGMF, dgmf::MethodParameters())
    ->Deform(
      problem, &mapping, dgmf::DeformationOutputs{ deformed.data(), &store }, dgmf::SerialFor);
  EXPECT_TRUE(SameBits(deformed, expected));
  EXPECT_TRUE(SameBits(store.Get(dgmf::names::F), f));
}

TEST(MethodInterface, InterpolationMethodsGiveTheBitsOfTheirFunctions)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(24, 8, 300);
  const dgmf::RigidMotion motion = Rotation(30);
  const dgmf::BoundaryMotion boundary = dgmf::GatherBoundaryMotion(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), motion, nullptr);
  const dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  std::vector<double> expected(set.Points.size()), deformed(set.Points.size());
  const std::size_t inverted =
    dgmf::DeformDGM(mapping, boundary, set.Points.data(), expected.data(), dgmf::SerialFor);
  dgmf::DeformationReport report =
    dgmf::CreateMethod(dgmf::Method::DGM, dgmf::MethodParameters())
      ->Deform(ProblemOf(set, motion), &mapping, dgmf::DeformationOutputs{ deformed.data() },
        dgmf::SerialFor);
  EXPECT_TRUE(SameBits(deformed, expected));
  ASSERT_FALSE(report.Values.empty());
  EXPECT_EQ(report.Values[0].Name, dgmf::names::InvertedGraphElementCount);
  EXPECT_EQ(report.Values[0].Values[0], static_cast<double>(inverted));

  const double length = dgmf::DeformIDW(boundary, dgmf::IDWParameters(), set.Points.data(),
    set.Size(), expected.data(), dgmf::SerialFor);
  report = dgmf::CreateMethod(dgmf::Method::IDW, dgmf::MethodParameters())
             ->Deform(ProblemOf(set, motion), nullptr, dgmf::DeformationOutputs{ deformed.data() },
               dgmf::SerialFor);
  EXPECT_TRUE(SameBits(deformed, expected));
  ASSERT_EQ(report.Values.size(), 1u);
  EXPECT_EQ(report.Values[0].Name, dgmf::names::IDWReferenceLength);
  EXPECT_EQ(report.Values[0].Values[0], length);
}

TEST(MethodInterface, ParametersAreCheckedWhenTheMethodIsCreated)
{
  dgmf::MethodParameters bad;
  bad.StaticR0 = 0.5;
  ExpectRejected([&]() { dgmf::CreateMethod(dgmf::Method::DGMF, bad); }, "r0s");
  bad = dgmf::MethodParameters();
  bad.Damping = static_cast<dgmf::DampingFunction>(9);
  ExpectRejected([&]() { dgmf::CreateMethod(dgmf::Method::DGM, bad); }, "damping function");
  bad = dgmf::MethodParameters();
  bad.SupportRadius = -1.0;
  ExpectRejected([&]() { dgmf::CreateMethod(dgmf::Method::RBF, bad); }, "support radius");
  bad = dgmf::MethodParameters();
  bad.RepairThreshold = 1.5;
  ExpectRejected([&]() { dgmf::CreateMethod(dgmf::Method::DGMF, bad); }, "repair threshold");
  ExpectRejected([&]()
    { dgmf::CreateMethod(static_cast<dgmf::Method>(7), dgmf::MethodParameters()); },
    "unknown deformation method");
}

TEST(ProblemValidation, BadValuesGetTheMessagesTheFilterShows)
{
  dgmf_test::NodeSet set = dgmf_test::CircleInSquare(16, 6, 40);
  const auto validate = [](const dgmf::DeformationProblem& problem)
  { return dgmf::ValidateProblem(problem, true); };
  std::vector<double> displacement(set.Points.size(), 0.0);
  dgmf::DeformationProblem problem = ProblemOf(set, Rotation(10));
  EXPECT_TRUE(validate(problem).empty());
  problem.Displacement = displacement.data();
  displacement[3 * 5 + 1] = std::numeric_limits<double>::infinity();
  ExpectRejected([&]() { validate(problem); }, "NaN or infinite values, or values of magnitude");
  ExpectRejected([&]() { validate(problem); }, "(point 5)");
  displacement[3 * 5 + 1] = 1e100; // finite, but its square overflows
  ExpectRejected([&]() { validate(problem); }, "(point 5)");
  displacement[3 * 5 + 1] = 0.0;
  displacement[3 * 7 + 2] = 0.25; // off the plane of a 2D mesh
  ExpectRejected([&]() { validate(problem); }, "non-zero z component (point 7)");
  problem.Displacement = nullptr;
  problem.Motions[0].AnglesDegrees[0] = 5.0;
  ExpectRejected([&]() { validate(problem); }, "2D mesh");
  problem.Motions[0] = Rotation(800.0);
  ExpectRejected([&]() { validate(problem); }, "within [-720, 720]");
  problem.Motions[0] = Rotation(10.0);
  problem.NumberOfBodies = 2; // two bodies, one motion
  ExpectRejected([&]() { validate(problem); }, "2 bodies but 1 rigid motions");
  problem.NumberOfBodies = 0;
  set.Points[3 * 50] = std::numeric_limits<double>::quiet_NaN();
  ExpectRejected([&]() { validate(problem); }, "NaN or infinite point coordinates");
  ExpectRejected([&]() { validate(problem); }, "(point 50)");
  EXPECT_NO_THROW(dgmf::ValidateProblem(problem, false)); // the graph methods check it there
  set = dgmf_test::CircleInSquare(16, 6, 40);
  for (dgmf::NodeKind& kind : set.Kinds)
  {
    kind = kind == dgmf::NodeKind::MovingBoundary ? dgmf::NodeKind::StaticBoundary : kind;
  }
  const std::vector<std::string> warnings = validate(ProblemOf(set, Rotation(10)));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("No node is marked as moving"), std::string::npos);
}

TEST(ProblemValidation, MarkerValuesBecomeKindsOrANamedError)
{
  std::vector<dgmf::NodeKind> kinds(4);
  dgmf::MarkerToNodeKinds(std::vector<int>{ 0, 1, 2, 1 }, kinds.data());
  EXPECT_EQ(kinds[2], dgmf::NodeKind::MovingBoundary);
  EXPECT_EQ(kinds[3], dgmf::NodeKind::StaticBoundary);
  ExpectRejected(
    [&]() {
      dgmf::MarkerToNodeKinds(std::vector<float>{ 0, 1, 1.5f, 2 }, kinds.data());
    },
    "has the value 1.5 at point 2");
  ExpectRejected(
    [&]() {
      dgmf::MarkerToNodeKinds(std::vector<double>{ 0, -1 }, kinds.data());
    },
    "has the value -1 at point 1");
  // A value next to an allowed one is shown as it is, not rounded to it.
  ExpectRejected(
    [&]() {
      dgmf::MarkerToNodeKinds(std::vector<double>{ 0, 2.0000001 }, kinds.data());
    },
    "has the value 2.0000001 at point 1");
  ExpectRejected([&]()
    { dgmf::MarkerToNodeKinds(std::vector<double>{ 1.0 + 0x1p-45 }, kinds.data()); },
    "has the value 1.0000000000000284 at point 0");
  // A subnormal value is named too (std::stod threw out_of_range on it, the message was "stod").
  ExpectRejected(
    [&]() {
      dgmf::MarkerToNodeKinds(std::vector<double>{ 0, 1e-310 }, kinds.data());
    },
    "has the value 1e-310 at point 1");
}

TEST(ProblemValidation, BodyIdsSetTheKindsOrGetANamedError)
{
  using K = dgmf::NodeKind;
  std::vector<K> kinds = { K::Interior, K::StaticBoundary, K::MovingBoundary, K::StaticBoundary };
  std::vector<std::int32_t> ids(4);
  EXPECT_EQ(dgmf::ResolveBodyIds(
              std::vector<double>{ 0, 2, 1, 0 }.data(), 4, false, kinds.data(), ids.data()),
    2);
  EXPECT_EQ(kinds[1], K::MovingBoundary); // a body node moves
  EXPECT_EQ(ids[1], 2);
  kinds = { K::Interior, K::StaticBoundary, K::MovingBoundary, K::StaticBoundary };
  dgmf::ResolveBodyIds(
    std::vector<double>{ 0, 0, 0, 0 }.data(), 4, false, kinds.data(), ids.data());
  EXPECT_EQ(kinds[2], K::StaticBoundary); // no body and no marker: static
  kinds = { K::Interior, K::StaticBoundary, K::MovingBoundary, K::StaticBoundary };
  ExpectRejected(
    [&]()
    {
      dgmf::ResolveBodyIds(
        std::vector<double>{ 0, 0, 0, 0 }.data(), 4, true, kinds.data(), ids.data());
    },
    "marked moving (2), the body id 0");
  ExpectRejected(
    [&]()
    {
      dgmf::ResolveBodyIds(
        std::vector<double>{ 1, 0, 1, 0 }.data(), 4, true, kinds.data(), ids.data());
    },
    "it is not a boundary node");
  ExpectRejected(
    [&]()
    {
      dgmf::ResolveBodyIds(
        std::vector<double>{ 0, 0.5, 1, 0 }.data(), 4, true, kinds.data(), ids.data());
    },
    "has the value 0.5 at point 1");
}
