// Tests src/base/registry.hpp: types registered by name in order (the first is the default),
// created with their constructor's arguments, described for the "Type" documentation; a name
// registered twice or an unknown name is an internal error.
#include "base/registry.hpp"

#include <gtest/gtest.h>

#include <string>

namespace
{
struct Shape
{
  virtual ~Shape() = default;
  virtual double area() const = 0;
};

struct Square final : Shape
{
  static std::string description() { return "a square of side s"; }
  static Teuchos::ParameterList valid_parameters()
  {
    Teuchos::ParameterList p;
    p.set("Side", 1.0, "s [m]");
    return p;
  }
  explicit Square(const double s) : s_(s) {}
  double area() const override { return s_ * s_; }
  double s_;
};

struct Disc final : Shape
{
  static std::string description() { return "a disc of radius s"; }
  static Teuchos::ParameterList valid_parameters() { return {}; }
  explicit Disc(const double s) : s_(s) {}
  double area() const override { return 3.0 * s_ * s_; }
  double s_;
};
} // namespace

TEST(Registry, CreatesDescribesAndRejects)
{
  kiln::Registry<Shape, double> registry;
  registry.add<Square>("Square").add<Disc>("Disc");
  EXPECT_EQ(registry.names(), (std::vector<std::string>{"Square", "Disc"}));
  EXPECT_EQ(registry.create("Square", 2.0)->area(), 4.0);
  EXPECT_EQ(registry.create("Disc", 2.0)->area(), 12.0);
  EXPECT_EQ(registry.describe(), "\"Square\": a square of side s; \"Disc\": a disc of radius s");
  ASSERT_NE(registry.find("Square"), nullptr);
  EXPECT_TRUE(registry.find("Square")->parameters.isParameter("Side"));
  EXPECT_EQ(registry.find("Triangle"), nullptr);
  EXPECT_THROW(registry.create("Triangle", 1.0), kiln::InternalError);
  EXPECT_THROW(registry.add<Disc>("Square"), kiln::InternalError);
}
