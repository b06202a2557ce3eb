/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The effect report (effectReport.H): per declared effect, measures of
    its influence from the run itself, with thresholds and verdicts.
\*---------------------------------------------------------------------------*/
#include "effectReport.H"
#include "solidModel.H"
#include "timeIntegrator.H"
#include "contactModel.H"
#include "solidContact.H"
#include "fluidRegion.H"
#include "vtkWriter.H"
#include "formError.H"
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::effectReport::effectReport(scalar threshold)
:
    threshold_(threshold)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::effectReport::start(const form::solidModel& model, scalar since)
{
    work_.start(model);
    maxKinetic_ = 0;
    maxInternal_ = 0;
    maxInertialReaction_ = 0;
    maxReaction_ = 0;
    maxPressureSpread_ = -1;
    maxViscousRatio_ = -1;
    since_ = since;
}


void Foam::effectReport::record
(
    const form::solidModel& model,
    const form::timeIntegrator* dynamicStep,
    const fluidRegion* fluid
)
{
    work_.add(model);
    maxInternal_ = max(maxInternal_, mag(work_.internalWork));
    if (dynamicStep)
    {
        maxKinetic_ = max(maxKinetic_, dynamicStep->energy().kinetic);
        // The reactions of the prescribed dofs and their inertial part
        const form::vecX& fi = model.internalForce();
        const form::vecX& fm = model.inertiaForce();
        scalar r2 = 0, m2 = 0;
        for (int d : model.prescribedDofs())
        {
            const scalar m = fm.size() ? fm(d) : 0.0;
            r2 += sqr(fi(d) + m);
            m2 += sqr(m);
        }
        maxReaction_ = max(maxReaction_, std::sqrt(r2));
        maxInertialReaction_ = max(maxInertialReaction_, std::sqrt(m2));
    }
    if (fluid)
    {
        const ALENavierStokes::interfaceLoad l = fluid->interfaceLoad();
        if (l.valid)
        {
            maxPressureSpread_ = max(maxPressureSpread_, l.pressureSpread);
            maxViscousRatio_ = max(maxViscousRatio_, l.viscousRatio);
        }
    }
}


Foam::dictionary Foam::effectReport::state() const
{
    dictionary d;
    const std::vector<double> w = work_.state();
    scalarList l(w.size());
    forAll(l, i) l[i] = w[i];
    d.add("work", l);
    d.add("maxKinetic", maxKinetic_);
    d.add("maxInternal", maxInternal_);
    d.add("maxInertialReaction", maxInertialReaction_);
    d.add("maxReaction", maxReaction_);
    d.add("maxPressureSpread", maxPressureSpread_);
    d.add("maxViscousRatio", maxViscousRatio_);
    d.add("since", since_);
    return d;
}


bool Foam::effectReport::setState
(
    const dictionary& d,
    const form::solidModel& model
)
{
    if (!d.found("work")) return false;
    const scalarList l(d.get<scalarList>("work"));
    work_.setState(std::vector<double>(l.begin(), l.end()), model.nDofs());
    maxKinetic_ = d.get<scalar>("maxKinetic");
    maxInternal_ = d.get<scalar>("maxInternal");
    maxInertialReaction_ = d.get<scalar>("maxInertialReaction");
    maxReaction_ = d.get<scalar>("maxReaction");
    maxPressureSpread_ = d.get<scalar>("maxPressureSpread");
    maxViscousRatio_ = d.get<scalar>("maxViscousRatio");
    since_ = d.get<scalar>("since");
    return true;
}


std::vector<Foam::effectReport::line> Foam::effectReport::lines
(
    const form::solidModel& model,
    const solidContact* contact,
    bool dynamicScene,
    const fluidRegion* fluid
) const
{
    std::vector<line> out;
    const scalar tol = threshold_;
    // "name value" pairs for a note
    const auto values = [](std::initializer_list<std::pair<const char*, scalar>> v)
    {
        std::ostringstream os;
        os << std::setprecision(4);
        const char* sep = "";
        for (const auto& p : v)
        {
            os << sep << p.first << ' ' << p.second;
            sep = ", ";
        }
        return os.str();
    };
    // a/b, or GREAT when b vanishes and a does not
    const auto ratio = [](scalar a, scalar b)
    {
        return b > VSMALL ? a/b : a > VSMALL ? GREAT : 0.0;
    };
    const auto measure = [&]
    (
        const word& effect, const word& name, scalar value,
        const std::string& negligible, const std::string& matters
    )
    {
        line l;
        l.effect = effect;
        l.measure = name;
        l.value = value;
        l.threshold = tol;
        l.matters = value >= tol;
        l.note = l.matters ? matters : negligible;
        out.push_back(l);
        return out.size() - 1;
    };

    if (dynamicScene)
    {
        const std::size_t i = measure
        (
            "inertia", "kineticToInternal",
            ratio(maxKinetic_, maxInternal_),
            "the kinetic energy is negligible: a static analysis would do",
            "the kinetic energy matters"
        );
        out[i].note += "; " + values
        (
            {{"max T", maxKinetic_}, {"max |W_int|", maxInternal_}}
        );
        if (maxReaction_ > VSMALL)
        {
            measure
            (
                "inertia", "inertialReaction",
                ratio(maxInertialReaction_, maxReaction_),
                "the reactions are static",
                "inertia forces are part of the reactions"
            );
        }
    }
    if (model.dissipative())
    {
        const scalar D = model.plasticDissipation();
        const std::size_t i = measure
        (
            "plasticity", "plasticDissipation",
            ratio(D, max(mag(work_.internalWork), D)),
            D > 0 ? "little plastic flow" : "the run stayed elastic",
            "the plastic flow dissipates energy"
        );
        out[i].note += "; " + values
        (
            {{"D_p", D}, {"W_int", work_.internalWork}}
        );
    }
    if (contact)
    {
        const form::contactModel& cm = contact->model();
        bool friction = false;
        for (const form::contactPairSpec& p : cm.pairs())
        {
            friction = friction || p.friction > 0;
        }
        if (friction)
        {
            const scalar D = cm.frictionDissipation();
            const std::size_t i = measure
            (
                "friction", "frictionDissipation",
                ratio(D, mag(work_.externalWork) + D),
                "friction dissipates little: frictionless pairs would do",
                "friction dissipates energy"
            );
            out[i].note += "; " + values
            (
                {{"D_f", D}, {"W_ext", work_.externalWork}}
            );
        }
        // A yes/no line: did the tool's pairs (the pair) ever close?
        const auto touched = [&]
        (
            const std::string& name, bool yes, const std::string& whoYes,
            const std::string& whoNo
        )
        {
            line l;
            l.effect = "contact:" + name;
            l.measure = "touched";
            l.matters = yes;
            l.value = yes ? 1 : 0;
            l.note = yes ? whoYes : whoNo;
            out.push_back(l);
        };
        for (const form::rigidToolSpec& tool : cm.tools())
        {
            touched
            (
                tool.name, cm.touched(tool.name), "the tool touched the body",
                "the tool never touched the body: it is not needed (or check"
                " its profile, motion and pairs)"
            );
        }
        // Pairs between deformable bodies (no tool)
        for (const form::contactPairSpec& p : cm.pairs())
        {
            if (!p.tool.empty()) continue;
            touched
            (
                p.name, cm.pairTouched(p.name), "the bodies touched",
                "the bodies never touched: the pair is not needed"
            );
        }
    }
    if (fluid && maxPressureSpread_ >= 0)
    {
        const bool matters =
            maxPressureSpread_ >= tol || maxViscousRatio_ >= tol;
        const std::string note = matters
          ? "the flow matters: the load is not a uniform pressure"
          : "a uniform pressure carries the load: fluidModel hydrostatic"
            " would do";
        for (const auto& m :
        {
            std::make_pair(word("pressureSpread"), maxPressureSpread_),
            std::make_pair(word("viscousTraction"), maxViscousRatio_)
        })
        {
            line l;
            l.effect = "fluid";
            l.measure = m.first;
            l.value = m.second;
            l.threshold = tol;
            l.matters = m.second >= tol;
            l.note = note;
            out.push_back(l);
        }
    }
    return out;
}


bool Foam::effectReport::write
(
    const std::vector<line>& lines,
    const fileName& path
) const
{
    // Six significant digits in the file, four in the log
    const auto number = [](scalar v, int digits = 6)
    {
        std::ostringstream os;
        if (v < 0) os << '-';
        else os << std::setprecision(digits) << v;
        return os.str();
    };
    std::ostringstream file;
    file<< "# formFoam effect report: per declared effect, a measure of its"
        << " influence from this run (effectReport.H)";
    if (since_ >= 0) file << ", from the restart at t = " << since_;
    file<< "\n# effect measure value threshold verdict note\n";
    Info<< nl << "Effects (measured by this run; negligible below the"
        << " threshold";
    if (since_ >= 0) Info<< "; from the restart at t = " << since_;
    Info<< ")" << nl;
    if (lines.empty())
    {
        Info<< "    none declared beyond the solid's elasticity" << nl;
    }
    for (const line& l : lines)
    {
        const char* verdict = l.matters ? "matters" : "negligible";
        file<< l.effect << ' ' << l.measure << ' ' << number(l.value) << ' '
            << number(l.threshold) << ' ' << verdict << ' ' << l.note
            << '\n';
        Info<< "    " << l.effect.c_str() << ": " << l.measure.c_str()
            << ' ' << number(l.value, 4).c_str();
        if (l.threshold >= 0)
        {
            Info<< (l.matters ? " >= " : " < ")
                << number(l.threshold, 4).c_str();
        }
        Info<< ", " << verdict << " (" << l.note.c_str() << ")" << nl;
    }
    Info<< endl;
    try
    {
        form::writeFileAtomic(path, file.str());
    }
    catch (const form::numericalError& err)
    {
        Info<< "    cannot write " << path << ": " << err.what() << endl;
        return false;
    }
    return true;
}


// ************************************************************************* //
