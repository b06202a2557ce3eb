// solidElement run-time selection.
#include "solidElement.H"
#include "formError.H"
#include <gtest/gtest.h>

using namespace form;

TEST(solidElement, registryAndValidTypes)
{
    EXPECT_EQ
    (
        solidElement::validTypes(),
        "Hex27 Hex27P4 Hex8 Hex8P1 Q4 Q4P1 Q9 Q9P3"
    );
    for (const char* t : {"Q4", "Q4P1", "Q9", "Q9P3"})
    {
        EXPECT_EQ(solidElement::New(t, analysisType::planeStrain)->type(), t);
    }
}

TEST(solidElement, unknownTypeListsValidNames)
{
    try
    {
        solidElement::New("Q8", analysisType::planeStrain);
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "elementType");
        EXPECT_EQ(std::string(e.what()),
                  "unknown element type 'Q8'; valid for planeStrain: Q4 Q4P1"
                  " Q9 Q9P3");
    }
    try
    {
        solidElement::New("Q8", analysisType::solid3D);
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_NE
        (
            std::string(e.what()).find
            (
                std::string("valid for ") + analysisTypeName(analysisType::solid3D)
              + ": Hex27 Hex27P4 Hex8 Hex8P1"
            ),
            std::string::npos
        ) << e.what();
    }
}

TEST(solidElement, quadsRejectSolid3D)
{
    try
    {
        solidElement::New("Q9P3", analysisType::solid3D);
        FAIL() << "no exception";
    }
    catch (const inputError& e)
    {
        EXPECT_EQ(e.entry(), "analysisType");
    }
}
