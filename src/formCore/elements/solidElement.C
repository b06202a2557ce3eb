/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Run-time selection of form::solidElement (see solidElement.H).
\*---------------------------------------------------------------------------*/
#include "solidElement.H"
#include "formError.H"

namespace form
{

std::map<std::string, solidElement::factoryFn>& solidElement::registry()
{
    // Function-local static: filled by the element files at static
    // initialisation, independent of their order
    static std::map<std::string, factoryFn> table;
    return table;
}


std::string solidElement::validTypes()
{
    std::string names;
    for (const auto& entry : registry())
    {
        names += (names.empty() ? "" : " ") + entry.first;
    }
    return names;
}


std::unique_ptr<solidElement> solidElement::New
(
    const std::string& type,
    analysisType analysis
)
{
    const auto it = registry().find(type);
    if (it == registry().end())
    {
        // The names that make an element for this analysis (quads in 2D,
        // hexahedra in 3D)
        std::string names;
        for (const auto& entry : registry())
        {
            try
            {
                entry.second(analysis);
                names += (names.empty() ? "" : " ") + entry.first;
            }
            catch (const inputError&) {}
        }
        throw inputError
        (
            "elementType",
            "unknown element type '" + type + "'; valid for "
          + analysisTypeName(analysis) + ": " + names
        );
    }
    return it->second(analysis);
}


infSupMatrices solidElement::infSup(const matX&) const
{
    throw numericalError
    (
        "element type '" + type() + "' provides no inf-sup test matrices"
    );
}

} // namespace form
