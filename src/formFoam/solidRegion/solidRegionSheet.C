/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    solidRegion (solidRegion.H): what a forming engineer reads from a
    formed sheet (shells): the thickness, the principal surface strains
    and the forming limit margin (surfaceStrain.H), as extremes over the
    elements for the summary; the forming limit curve of solidProperties.
\*---------------------------------------------------------------------------*/
#include "solidRegion.H"
#include "shellSet.H"
#include "dictionaryChecks.H"
#include "formError.H"
#include "OSspecific.H"
#include "vtkWriter.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::solidRegion::readFormingLimit()
{
    if (!properties_.found("formingLimit")) return;
    const dictionary& d = subDictOf
    (
        properties_, "formingLimit", "{ type table; points ((minor major) ...); }"
    );
    const fileName file = properties_.objectPath();
    if (!form::shellSet::isShellType(elementType_))
    {
        FatalIOErrorInFunction(d)
            << "Entry 'formingLimit' in " << file << ": a forming limit"
            << " curve needs shell elements (the sheet's surface strains);"
            << " elementType is " << elementType_ << exit(FatalIOError);
    }
    const word type = d.get<word>("type");
    try
    {
        if (type == "table")
        {
            checkKeywords(d, {"type", "points"});
            const List<Tuple2<scalar, scalar>> pts =
                d.get<List<Tuple2<scalar, scalar>>>("points");
            std::vector<std::pair<double, double>> p;
            for (const auto& q : pts) p.emplace_back(q.first(), q.second());
            formingLimit_.reset
            (
                new form::formingLimit(form::formingLimit::table(p))
            );
        }
        else if (type == "keelerBrazier")
        {
            checkKeywords(d, {"type", "thickness", "n"});
            const dictionary& mat = properties_.subDict("material");
            scalar n = -1;
            if (d.found("n"))
            {
                n = d.get<scalar>("n");
            }
            else if
            (
                mat.found("hardening") && mat.isDict("hardening")
             && mat.subDict("hardening").getOrDefault<word>("type", "")
             == "swift"
            )
            {
                n = mat.subDict("hardening").get<scalar>("n");
            }
            else
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'formingLimit/n' in " << file << ": the"
                    << " Keeler-Brazier estimate needs the hardening"
                    << " exponent n (given, or the material's Swift"
                    << " hardening's)" << exit(FatalIOError);
            }
            // The section's thickness, or the mesh's (the sheet's at its
            // first shell node) where the section gives none
            scalar tSheet = readShellSection().thickness;
            const form::shellSet* shells = model_->shells();
            for (int n = 0; !(tSheet > 0) && shells && n < feMesh_->feMesh().nNodes(); ++n)
            {
                if (shells->shellNode(n) >= 0) tSheet = shells->thickness(n);
            }
            const scalar t = d.getOrDefault<scalar>("thickness", tSheet);
            formingLimit_.reset
            (
                new form::formingLimit(form::formingLimit::keelerBrazier(t, n))
            );
        }
        else
        {
            FatalIOErrorInFunction(d)
                << "Entry 'formingLimit/type' in " << file << ": unknown '"
                << type << "'; valid: table keelerBrazier"
                << exit(FatalIOError);
        }
    }
    catch (const form::inputError& err)
    {
        FatalIOErrorInFunction(d)
            << "Entry 'formingLimit/" << err.entry().c_str() << "' in "
            << file << ": " << err.what() << exit(FatalIOError);
    }
    Info<< "    forming limit: " << formingLimit_->description().c_str()
        << endl;
    // The curve for plots: postProcessing/formingLimit.<region>.dat
    std::string text =
        "# forming limit curve of solid region " + name_ + ": "
      + formingLimit_->description() + "\n# minorStrain majorStrain\n";
    for (const auto& p : formingLimit_->sample(-0.4, 0.4, 80))
    {
        text += std::to_string(p.first) + " " + std::to_string(p.second) + "\n";
    }
    const fileName dir = runTime_.path()/"postProcessing";
    mkDir(dir);
    form::writeFileAtomic(dir/("formingLimit." + name_ + ".dat"), text);
}


std::vector<form::elementResult> Foam::solidRegion::shellResults
(
    const dictionary& dict
) const
{
    if (!form::shellSet::isShellType(elementType_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'type' in " << dict.name() << ": solid region '"
            << name_ << "' has no shell elements (elementType "
            << elementType_ << ")" << exit(FatalIOError);
    }
    if (!holdShellResults_) return model_->elementResults();
    if (heldShellResults_.empty()) heldShellResults_ = model_->elementResults();
    return heldShellResults_;
}


Foam::scalar Foam::solidRegion::shellThickness
(
    bool largest,
    const dictionary& dict
) const
{
    const std::vector<form::elementResult> results = shellResults(dict);
    const form::feMesh& fe = feMesh_->feMesh();
    scalar value = largest ? -GREAT : GREAT;
    std::size_t k = 0;
    for (const form::elementBlock& b : fe.blocks)
    {
        for (int e = 0; e < b.nElements(); ++e, ++k)
        {
            const scalar t = b.shell.thickness*results[k].meanThicknessStretch;
            value = largest ? max(value, t) : min(value, t);
        }
    }
    return value;
}


Foam::scalar Foam::solidRegion::surfaceStrain
(
    bool major,
    bool largest,
    const dictionary& dict
) const
{
    scalar value = largest ? -GREAT : GREAT;
    for (const form::elementResult& r : shellResults(dict))
    {
        const scalar e = major ? r.majorStrain : r.minorStrain;
        value = largest ? max(value, e) : min(value, e);
    }
    return value;
}


Foam::scalar Foam::solidRegion::formingLimitMargin
(
    const dictionary& dict
) const
{
    const std::vector<form::elementResult> results = shellResults(dict);
    if (!formingLimit_)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'type' in " << dict.name() << ": a forming limit"
            << " margin needs a forming limit curve: give formingLimit"
            << " in constant/" << name_ << "/solidProperties"
            << exit(FatalIOError);
    }
    scalar value = GREAT;
    for (const form::elementResult& r : results)
    {
        value = min(value, (*formingLimit_)(r.minorStrain) - r.majorStrain);
    }
    return value;
}


// ************************************************************************* //
