/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of formTypes.H: the basic types of formCore, the
    finite-element kernel library.
\*---------------------------------------------------------------------------*/
#include "formTypes.H"
#include "formError.H"

const char* form::analysisTypeName(analysisType t)
{
    switch (t)
    {
        case analysisType::planeStrain: return "planeStrain";
        case analysisType::axisymmetric: return "axisymmetric";
        case analysisType::solid3D: return "solid3D";
    }
    return "unknown";
}

form::analysisType form::analysisTypeFromName(const std::string& name)
{
    if (name == "planeStrain") return analysisType::planeStrain;
    if (name == "axisymmetric") return analysisType::axisymmetric;
    if (name == "solid3D") return analysisType::solid3D;
    throw inputError
    (
        "analysisType",
        "unknown analysisType '" + name
      + "'; valid: planeStrain axisymmetric solid3D"
    );
}
