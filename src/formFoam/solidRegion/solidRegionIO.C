/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
    solidRegion: output and restart state (solidRegion.H): the fields and
    restart state of a time (written into the temporary directory of
    formScene::writeTime), the VTK series, and the state read on a restart
\*---------------------------------------------------------------------------*/
#include "solidRegion.H"
#include "shellSet.H"
#include "contactModel.H"
#include "dictionaryChecks.H"
#include "Function1.H"
#include "IFstream.H"
#include "IOField.H"
#include "OSspecific.H"
#include "pointFields.H"
#include "pointLocator.H"
#include "materialInput.H"
#include "Tuple2.H"
#include "volFields.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::solidRegion::write()
{
    const word timeName = runTime_.timeName();
    const form::feMesh& fe = feMesh_->feMesh();
    const form::matX U = model_->displacement();
    const std::vector<form::elementResult> results = model_->elementResults();

    // (formScene::writeTime names the time with the temporary directory
    // of the time being written)
    const auto io = [&](const word& fieldName)
    {
        return IOobject
        (
            fieldName, timeName, *mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        );
    };

    // Nodal displacement at the polyMesh points
    pointVectorField pointD
    (
        io("pointD"),
        pointMesh::New(*mesh_),
        dimensionedVector(dimLength, Zero)
    );
    const pointField& pts = mesh_->points();
    const form::shellSet* shells = model_->shells();
    forAll(pts, pointi)
    {
        const label n = feMesh_->pointToNode()[pointi];
        if (n >= 0)
        {
            pointD[pointi] =
                feMesh_->toSpace(pts[pointi], U.row(n).transpose());
        }
        if (n >= 0 && shells && shells->shellNode(n) >= 0)
        {
            // A point of the sheet's faces: on its node's director line,
            // at z along the initial director; it turns with the director
            const form::vec3 V0 = shells->initialDirector(n);
            const form::vec3 V =
                shells->director(n, model_->dofs(), model_->U());
            const form::vec3 d =
                form::vec3(pts[pointi].x(), pts[pointi].y(), pts[pointi].z())
              - fe.X.row(n).transpose();
            const form::vec3 turn = d.dot(V0)*(V - V0);
            pointD[pointi] += vector(turn(0), turn(1), turn(2));
        }
    }

    volVectorField D(io("D"), *mesh_, dimensionedVector(dimLength, Zero));
    volSymmTensorField sigma
    (
        io("sigma"), *mesh_, dimensionedSymmTensor(dimPressure, Zero)
    );
    volScalarField sigmaEq(io("sigmaEq"), *mesh_, dimensionedScalar(dimPressure, Zero));
    volScalarField p(io("p"), *mesh_, dimensionedScalar(dimPressure, Zero));
    volScalarField epsilonEq(io("epsilonEq"), *mesh_, dimensionedScalar(dimless, Zero));

    const form::elementBlock& blk = fe.blocks[0];
    const int nDim = fe.nDim;
    form::vecX Nc;
    form::matX dNc;
    if (shells)
    {
        // the mid-surface's centre (MITC4: 4 nodes, MITC3+: 3)
        Nc = form::vecX::Constant
        (
            blk.nodesPerElement, 1.0/blk.nodesPerElement
        );
    }
    else
    {
        form::elementShape
        (
            nDim, blk.nodesPerElement, form::vecX::Zero(nDim), Nc, dNc
        );
    }
    const vectorField& C = mesh_->C();
    forAll(C, celli)
    {
        form::vecX u = form::vecX::Zero(nDim);
        for (int a = 0; a < blk.nodesPerElement; ++a)
        {
            u += Nc(a)*U.row(blk.nodes(celli)[a]).transpose();
        }
        D[celli] = feMesh_->toSpace(C[celli], u);

        // Cauchy stress from the FE frame (2D: first, second, out-of-plane
        // direction) to the polyMesh space
        const form::elementResult& r = results[celli];
        tensor s(Zero);
        for (direction i = 0; i < 3; ++i)
        {
            for (direction j = 0; j < 3; ++j)
            {
                s(i, j) = r.cauchy(i, j);
            }
        }
        if (nDim == 2)
        {
            const vector e1 =
                feMesh_->toSpace(C[celli], Eigen::Vector2d(1, 0));
            const vector e2 =
                feMesh_->toSpace(C[celli], Eigen::Vector2d(0, 1));
            const vector e3 = e1 ^ e2;
            const tensor Q(e1, e2, e3);     // rows: basis vectors
            s = Q.T() & s & Q;
        }
        sigma[celli] = symm(s);
        sigmaEq[celli] = sqrt(1.5*magSqr(dev(sigma[celli])));
        p[celli] = r.pressure;
        epsilonEq[celli] = r.equivalentStrain;
    }
    // calculated patches: face values from the nodal displacements
    forAll(D.boundaryField(), patchi)
    {
        fvPatchVectorField& pf = D.boundaryFieldRef()[patchi];
        if (isA<emptyFvPatch>(pf.patch()) || isA<wedgeFvPatch>(pf.patch()))
        {
            continue;
        }
        const polyPatch& pp = pf.patch().patch();
        forAll(pp, i)
        {
            const face& f = pp[i];
            vector sum(Zero);
            for (const label pointi : f) sum += pointD[pointi];
            pf[i] = sum/f.size();
        }
    }
    D.correctBoundaryConditions();

    IOField<vector> feU(io("feU"), vectorField(fe.nNodes(), Zero));
    for (int n = 0; n < fe.nNodes(); ++n)
    {
        feU[n] = vector(U(n, 0), U(n, 1), nDim == 3 ? U(n, 2) : 0);
    }

    // Material history (plastic strains, back stresses...) for restarts
    const auto& states = model_->materialStates();
    label nHist = 0;
    for (const auto& el : states)
    {
        for (const auto& q : el) nHist += q.history.size();
    }
    IOField<scalar> feHistory(io("feHistory"), scalarField(nHist, 0));
    {
        label k = 0;
        for (const auto& el : states)
        {
            for (const auto& q : el)
            {
                for (int i = 0; i < q.history.size(); ++i)
                {
                    feHistory[k++] = q.history(i);
                }
            }
        }
    }

    // Shells: the current thickness, the mid-surface's principal strains,
    // the stresses at the bottom, middle and top points through it, and
    // the director frames for restarts
    autoPtr<volScalarField> thickness, majorStrain, minorStrain, margin;
    PtrList<volSymmTensorField> layers;
    if (shells)
    {
        const char* names[3] = {"sigmaBottom", "sigmaMiddle", "sigmaTop"};
        layers.setSize(3);
        for (label l = 0; l < 3; ++l)
        {
            layers.set
            (
                l,
                new volSymmTensorField
                (
                    io(names[l]), *mesh_,
                    dimensionedSymmTensor(dimPressure, Zero)
                )
            );
            forAll(C, celli)
            {
                const form::mat3& m = results[celli].shellLayers[l];
                layers[l][celli] = symmTensor
                (
                    m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)
                );
            }
        }
        thickness.reset
        (
            new volScalarField
            (
                io("thickness"), *mesh_, dimensionedScalar(dimLength, Zero)
            )
        );
        majorStrain.reset
        (
            new volScalarField
            (
                io("majorStrain"), *mesh_, dimensionedScalar(dimless, Zero)
            )
        );
        minorStrain.reset
        (
            new volScalarField
            (
                io("minorStrain"), *mesh_, dimensionedScalar(dimless, Zero)
            )
        );
        forAll(C, celli)
        {
            (*thickness)[celli] =
                blk.shell.thickness*results[celli].meanThicknessStretch;
            (*majorStrain)[celli] = results[celli].majorStrain;
            (*minorStrain)[celli] = results[celli].minorStrain;
        }
        if (formingLimit_)
        {
            margin.reset
            (
                new volScalarField
                (
                    io("formingLimitMargin"), *mesh_,
                    dimensionedScalar(dimless, Zero)
                )
            );
            forAll(C, celli)
            {
                (*margin)[celli] =
                    (*formingLimit_)(results[celli].minorStrain)
                  - results[celli].majorStrain;
            }
        }
    }

    // Results at the case's writePrecision; the restart state at full
    // precision (a restart reproduces the run to round-off)
    bool ok = pointD.write();
    if (thickness) ok = thickness->write() && ok;
    if (majorStrain) ok = majorStrain->write() && minorStrain->write() && ok;
    if (margin) ok = margin->write() && ok;
    for (const volSymmTensorField& f : layers) ok = f.write() && ok;
    ok = D.write() && ok;
    ok = sigma.write() && ok;
    ok = sigmaEq.write() && ok;
    ok = p.write() && ok;
    ok = epsilonEq.write() && ok;
    const unsigned precision = IOstream::defaultPrecision(17);
    if (nHist) ok = feHistory.write() && ok;
    if (model_->contact())
    {
        // Contact multipliers, tool positions, committed slip origins
        const std::vector<double> cs = model_->contact()->state();
        IOField<scalar> contactState(io("contactState"), scalarField(cs.size()));
        forAll(contactState, i) contactState[i] = cs[i];
        ok = contactState.write() && ok;
    }
    // Loads of released constraints and tools (dof force t0 t1), for a
    // restart inside their ramps
    const std::vector<double> rl = model_->releaseLoads();
    if (!rl.empty())
    {
        IOField<scalar> released(io("feReleased"), scalarField(rl.size()));
        forAll(released, i) released[i] = rl[i];
        ok = released.write() && ok;
    }
    if (shells)
    {
        const std::vector<double> ss = model_->shellState();
        IOField<scalar> shellState(io("shellState"), scalarField(ss.size()));
        forAll(shellState, i) shellState[i] = ss[i];
        ok = shellState.write() && ok;
    }
    ok = feU.write() && ok;
    IOstream::defaultPrecision(precision);
    return ok;
}


void Foam::solidRegion::writeVTK()
{
    vtk_->write
    (
        runTime_.value(), feMesh_->feMesh(), model_->displacement(),
        model_->elementResults()
    );
}


void Foam::solidRegion::resumeVTK(scalar restartTime)
{
    vtk_->resume(restartTime);
}


form::matX Foam::solidRegion::displacementState
(
    const word& timeName,
    const dictionary& dict
) const
{
    IOobject io
    (
        "feU", timeName, *mesh_, IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    const form::feMesh& fe = feMesh_->feMesh();
    if (!io.typeHeaderOk<IOField<vector>>(true))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'since' in " << dict.name() << ": no state of time "
            << timeName << " (" << io.objectPath() << "): 'since' must be"
            << " the end of a process step or a written time"
            << exit(FatalIOError);
    }
    const IOField<vector> feU(io);
    if (feU.size() != fe.nNodes())
    {
        FatalIOErrorInFunction(dict)
            << "State " << feU.objectPath() << " has " << feU.size()
            << " nodes; the mesh of region '" << name_ << "' has "
            << fe.nNodes() << exit(FatalIOError);
    }
    form::matX U(fe.nNodes(), fe.nDim);
    for (int n = 0; n < fe.nNodes(); ++n)
    {
        for (int c = 0; c < fe.nDim; ++c) U(n, c) = feU[n][c];
    }
    return U;
}


bool Foam::solidRegion::readState(const word& timeName)
{
    IOobject io
    (
        "feU", timeName, *mesh_, IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (!io.typeHeaderOk<IOField<vector>>(true))
    {
        return false;
    }
    IOField<vector> feU(io);
    const form::feMesh& fe = feMesh_->feMesh();
    if (feU.size() != fe.nNodes())
    {
        FatalErrorInFunction
            << "Restart state " << feU.objectPath() << " has " << feU.size()
            << " nodes; the mesh of region '" << name_ << "' has "
            << fe.nNodes() << exit(FatalError);
    }
    form::vecX dU = -model_->U();
    for (int n = 0; n < fe.nNodes(); ++n)
    {
        for (int c = 0; c < fe.nDim; ++c)
        {
            dU(model_->dofs().dof(n, c)) += feU[n][c];
        }
    }
    model_->setDisplacement(model_->U() + dU);

    // Shells: the director frames (and with them the rotation unknowns)
    if (model_->shells())
    {
        IOobject sio
        (
            "shellState", timeName, *mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        if (!sio.typeHeaderOk<IOField<scalar>>(true))
        {
            FatalErrorInFunction
                << "Restart state of region '" << name_ << "' at time "
                << timeName << " has no shell directors (shellState), which"
                << " its shell elements need" << exit(FatalError);
        }
        IOField<scalar> ss(sio);
        try
        {
            model_->setShellState(std::vector<double>(ss.begin(), ss.end()));
        }
        catch (const form::numericalError& e)
        {
            FatalErrorInFunction
                << "Restart state " << ss.objectPath() << ": " << e.what()
                << exit(FatalError);
        }
    }

    // Material history, if the material has one
    std::vector<std::vector<form::materialState>> states =
        model_->materialStates();
    label nHist = 0;
    for (const auto& el : states)
    {
        for (const auto& q : el) nHist += q.history.size();
    }
    if (nHist)
    {
        IOobject hio
        (
            "feHistory", timeName, *mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        if (!hio.typeHeaderOk<IOField<scalar>>(true))
        {
            FatalErrorInFunction
                << "Restart state of region '" << name_ << "' at time "
                << timeName << " has no material history (feHistory), which"
                << " the material " << materialType_ << " needs"
                << exit(FatalError);
        }
        IOField<scalar> h(hio);
        if (h.size() != nHist)
        {
            FatalErrorInFunction
                << "Restart state " << h.objectPath() << " has " << h.size()
                << " history values; the model needs " << nHist
                << exit(FatalError);
        }
        label k = 0;
        for (auto& el : states)
        {
            for (auto& q : el)
            {
                for (int i = 0; i < q.history.size(); ++i) q.history(i) = h[k++];
            }
        }
        model_->setMaterialStates(states);
    }
    if (model_->contact())
    {
        IOobject cio
        (
            "contactState", timeName, *mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        if (!cio.typeHeaderOk<IOField<scalar>>(true))
        {
            FatalErrorInFunction
                << "Restart state of region '" << name_ << "' at time "
                << timeName << " has no contact state (contactState), which"
                << " the contact pairs of constant/contactProperties need"
                << exit(FatalError);
        }
        IOField<scalar> c(cio);
        try
        {
            model_->contact()->setState(std::vector<double>(c.begin(), c.end()));
        }
        catch (const form::numericalError& e)
        {
            FatalErrorInFunction
                << "Restart state " << c.objectPath() << ": " << e.what()
                << " (was constant/contactProperties changed?)"
                << exit(FatalError);
        }
    }
    // Shell contact: the offsets follow the restored state's thickness
    model_->updateShellContactThickness();
    // Releases begun before the restart: their loads (written only when
    // something was released); formScene then re-applies the release
    // actions of those steps without new loads
    IOobject rio
    (
        "feReleased", timeName, *mesh_,
        IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
    );
    if (rio.typeHeaderOk<IOField<scalar>>(true))
    {
        IOField<scalar> rl(rio);
        try
        {
            model_->setReleaseLoads(std::vector<double>(rl.begin(), rl.end()));
        }
        catch (const form::numericalError& e)
        {
            FatalErrorInFunction
                << "Restart state " << rl.objectPath() << ": " << e.what()
                << exit(FatalError);
        }
    }
    return true;
}


// ************************************************************************* //


Foam::scalar Foam::solidRegion::directorRotation
(
    const point& pt,
    const dictionary& dict
) const
{
    const form::shellSet* shells = model_->shells();
    if (!shells)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'type' in " << dict.name() << ": solid region '"
            << name_ << "' has no shell elements (elementType "
            << elementType_ << ")" << exit(FatalIOError);
    }
    const label node = nodeAt(pt, dict);
    const form::vec3 V0 = shells->initialDirector(node);
    const form::vec3 V = shells->director(node, model_->dofs(), model_->U());
    return std::atan2(V0.cross(V).norm(), V0.dot(V));
}
