// Reparam - the maps by their Mesh.CompoundParametrization value

#include <string>
#include <gtest/gtest.h>
#include "mapKind.h"

using namespace reparam;

TEST(mapKind, valuesAreTheOptionsValues)
{
  EXPECT_EQ((int)compoundParametrization::gmsh, 0);
  EXPECT_EQ((int)compoundParametrization::meanValue, 3);
  EXPECT_EQ((int)compoundParametrization::spectral, 5);
  EXPECT_EQ((int)compoundParametrization::automatic, 6);
}

TEST(mapKind, namesForTheLog)
{
  EXPECT_EQ(std::string(compoundParametrizationName(0)),
            "Gmsh built-in mean value");
  EXPECT_EQ(std::string(compoundParametrizationName(2)), "barycentric (Tutte)");
  EXPECT_EQ(std::string(compoundParametrizationName(4)),
            "finite element conformal (LSCM)");
  EXPECT_EQ(std::string(compoundParametrizationName(6)), "automatic");
  EXPECT_EQ(std::string(compoundParametrizationName(7)), "plane projection");
  EXPECT_EQ(std::string(compoundParametrizationName(8)), "unknown");
  EXPECT_EQ(std::string(compoundParametrizationName(-1)), "unknown");
}
