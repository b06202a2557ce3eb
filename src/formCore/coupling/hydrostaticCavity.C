/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    The hydrostatic fluid cavity (hydrostaticCavity.H).
\*---------------------------------------------------------------------------*/
#include "hydrostaticCavity.H"
#include "gaussLegendre.H"
#include "quadShape.H"
#include "formError.H"
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace form
{

hydrostaticCavity::hydrostaticCavity
(
    const feMesh& mesh,
    analysisType analysis,
    hydrostaticCavitySpec spec
)
:
    mesh_(mesh),
    dofs_(dofMap::of(mesh)),
    analysis_(analysis),
    spec_(std::move(spec)),
    p_(vecX::Zero(1))
{
    const std::string& n = spec_.name;
    if (analysis_ == analysisType::solid3D)
    {
        throw inputError
        (
            n, "fluid cavity '" + n + "': only plane strain and"
            " axisymmetric models (3D wetted faces are not implemented)"
        );
    }
    if (spec_.faceSets.empty())
    {
        throw inputError
        (
            n, "fluid cavity '" + n + "' has no wetted patch: it needs an"
            " interface with a solid"
        );
    }
    for (const std::string& fs : spec_.faceSets)
    {
        const auto it = mesh_.faceSets.find(fs);
        if (it == mesh_.faceSets.end() || it->second.empty())
        {
            std::string valid;
            for (const auto& f : mesh_.faceSets) valid += " " + f.first;
            throw inputError
            (
                n, "fluid cavity '" + n + "': wetted patch '" + fs
              + "' is not a boundary patch of the solid; patches:" + valid
            );
        }
        faces_.insert(faces_.end(), it->second.begin(), it->second.end());
    }
    if (!(spec_.bulkModulus > 0))
    {
        throw inputError
        (
            n, "fluid cavity '" + n + "': bulk modulus must be positive"
            " (or infinite for an incompressible fluid), got "
          + std::to_string(spec_.bulkModulus)
        );
    }
    if (!(spec_.initialVolume > 0) || !std::isfinite(spec_.initialVolume))
    {
        throw inputError
        (
            n, "fluid cavity '" + n + "': initial volume must be positive,"
            " got " + std::to_string(spec_.initialVolume)
        );
    }
    if (!spec_.injectedVolume && !spec_.pressure)
    {
        throw inputError
        (
            n, "fluid cavity '" + n + "': needs an injected volume (volume"
            " control) or a pressure (pressure control)"
        );
    }
    wetted0_ = wettedVolume(vecX::Zero(dofs_.nDofs()));
}


double hydrostaticCavity::wettedVolume
(
    const vecX& U,
    std::vector<int>* dofs,
    vecX* gradient,
    matX* hessian
) const
{
    const bool axi = analysis_ == analysisType::axisymmetric;
    std::vector<double> xi, w;
    gaussLegendre1D(3, xi, w);

    // Local numbering of the wetted nodes' dofs
    std::map<int, int> local;
    for (const feFace& f : faces_)
    {
        for (int node : f.nodes) local.emplace(node, 0);
    }
    int k = 0;
    for (auto& l : local) l.second = k++;
    const int nq = 2*k;
    if (dofs)
    {
        dofs->clear();
        for (const auto& l : local)
        {
            dofs->push_back(dofs_.dof(l.first, 0));
            dofs->push_back(dofs_.dof(l.first, 1));
        }
    }
    if (gradient) gradient->setZero(nq);
    if (hessian) hessian->setZero(nq, nq);

    double V = 0;
    vecX N, dN;
    for (const feFace& f : faces_)
    {
        const int n = int(f.nodes.size());
        std::vector<int> ix(n), iy(n);
        matX x(n, 2);
        for (int a = 0; a < n; ++a)
        {
            const int node = f.nodes[a];
            x(a, 0) = mesh_.X(node, 0) + U(dofs_.dof(node, 0));
            x(a, 1) = mesh_.X(node, 1) + U(dofs_.dof(node, 1));
            ix[a] = 2*local[node];
            iy[a] = ix[a] + 1;
        }
        for (std::size_t q = 0; q < xi.size(); ++q)
        {
            lineShape(n, xi[q], N, dN);
            const double X = N.dot(x.col(0));
            const double Y = N.dot(x.col(1));
            const double Xxi = dN.dot(x.col(0));
            const double W = axi ? 2*M_PI*X : 1.0;
            const double Wx = axi ? 2*M_PI : 0.0;
            V += w[q]*Y*Xxi*W;
            if (!gradient && !hessian) continue;
            for (int a = 0; a < n; ++a)
            {
                // dV/dy_a = N_a x' W;  dV/dx_a = y (N_a' W + x' W' N_a)
                if (gradient)
                {
                    (*gradient)(iy[a]) += w[q]*N(a)*Xxi*W;
                    (*gradient)(ix[a]) +=
                        w[q]*Y*(dN(a)*W + Xxi*Wx*N(a));
                }
                if (!hessian) continue;
                for (int b = 0; b < n; ++b)
                {
                    // d2V/dy_a dx_b = N_a (N_b' W + x' W' N_b)
                    const double yx =
                        w[q]*N(a)*(dN(b)*W + Xxi*Wx*N(b));
                    (*hessian)(iy[a], ix[b]) += yx;
                    (*hessian)(ix[b], iy[a]) += yx;
                    // d2V/dx_a dx_b = y W' (N_a' N_b + N_a N_b')
                    (*hessian)(ix[a], ix[b]) +=
                        w[q]*Y*Wx*(dN(a)*N(b) + N(a)*dN(b));
                }
            }
        }
    }
    return V;
}


double hydrostaticCavity::volume(const vecX& U) const
{
    return spec_.initialVolume + wettedVolume(U) - wetted0_;
}


double hydrostaticCavity::injected(double t) const
{
    return spec_.injectedVolume ? spec_.injectedVolume(t) : 0.0;
}


double hydrostaticCavity::fluidVolume(double p, double t) const
{
    const double Vm = spec_.initialVolume + injected(t);
    return std::isinf(spec_.bulkModulus)
        ? Vm : Vm*std::exp(-p/spec_.bulkModulus);
}


double hydrostaticCavity::wettedArea(const vecX& U) const
{
    const bool axi = analysis_ == analysisType::axisymmetric;
    std::vector<double> xi, w;
    gaussLegendre1D(3, xi, w);
    double A = 0;
    vecX N, dN;
    for (const feFace& f : faces_)
    {
        const int n = int(f.nodes.size());
        matX x(n, 2);
        for (int a = 0; a < n; ++a)
        {
            x(a, 0) = mesh_.X(f.nodes[a], 0) + U(dofs_.dof(f.nodes[a], 0));
            x(a, 1) = mesh_.X(f.nodes[a], 1) + U(dofs_.dof(f.nodes[a], 1));
        }
        for (std::size_t q = 0; q < xi.size(); ++q)
        {
            lineShape(n, xi[q], N, dN);
            const double ds = (x.transpose()*dN).norm();
            A += w[q]*ds*(axi ? 2*M_PI*N.dot(x.col(0)) : 1.0);
        }
    }
    return A;
}


void hydrostaticCavity::addToUnknowns(const vecX& dx)
{
    p_ += dx;
}


void hydrostaticCavity::beginIncrement(double, double, const vecX&)
{}


void hydrostaticCavity::evaluate
(
    double t,
    const vecX& U,
    vecX& fext,
    vecX& r,
    std::vector<triplet>* K
)
{
    const double p = p_(0);
    if (!std::isfinite(p))
    {
        throw numericalError
        (
            "fluid cavity '" + spec_.name + "': non-finite pressure"
        );
    }
    // Withdrawing more fluid than the cavity holds: no state can follow
    // (the fluid volume V_0 + V_inj would be <= 0), whatever the step
    if (volumeControlled() && !(spec_.initialVolume + injected(t) > 0))
    {
        char msg[256];
        std::snprintf
        (
            msg, sizeof(msg),
            "at t = %g the injected volume %g withdraws all the fluid of"
            " cavity '%s' (it holds %g at the start): the fluid volume"
            " V_0 + V_inj must stay positive",
            t, injected(t), spec_.name.c_str(), spec_.initialVolume
        );
        throw inputError("injectedVolume", msg);
    }
    std::vector<int> dofs;
    vecX g;
    matX H;
    const double Vw = wettedVolume(U, &dofs, &g, K ? &H : nullptr);
    const int N = int(fext.size());
    const int ip = N;   // the pressure's row/column (block-local 0)

    // f = p dV/du
    for (std::size_t i = 0; i < dofs.size(); ++i) fext(dofs[i]) += p*g(i);

    r.resize(1);
    if (volumeControlled())
    {
        const double V = spec_.initialVolume + Vw - wetted0_;
        const double Vf = fluidVolume(p, t);
        r(0) = V - Vf;
        if (!K) return;
        // -dr_p/dp = dV_f/dp = -V_f/K
        K->emplace_back
        (
            ip, ip,
            std::isinf(spec_.bulkModulus) ? 0.0 : -Vf/spec_.bulkModulus
        );
        for (std::size_t i = 0; i < dofs.size(); ++i)
        {
            K->emplace_back(ip, dofs[i], -g(i));
        }
    }
    else
    {
        const double c = spec_.initialVolume/spec_.referenceModulus;
        r(0) = c*(spec_.pressure(t) - p);
        if (!K) return;
        K->emplace_back(ip, ip, c);
    }
    for (std::size_t i = 0; i < dofs.size(); ++i)
    {
        // -d(p g)/dp = -g;  -d(p g)/du = -p H
        K->emplace_back(dofs[i], ip, -g(i));
        for (std::size_t j = 0; j < dofs.size(); ++j)
        {
            if (H(i, j) != 0) K->emplace_back(dofs[i], dofs[j], -p*H(i, j));
        }
    }
}


void hydrostaticCavity::commit(const vecX&)
{
    pCommitted_ = p_(0);
}


void hydrostaticCavity::revert()
{
    p_(0) = pCommitted_;
}


std::string hydrostaticCavity::unknownName(int) const
{
    return spec_.name + " pressure";
}


std::vector<double> hydrostaticCavity::state() const
{
    return {p_(0), pCommitted_};
}


void hydrostaticCavity::setState(const std::vector<double>& s)
{
    if (s.size() != 2)
    {
        throw numericalError
        (
            "hydrostaticCavity::setState: " + std::to_string(s.size())
          + " values, not 2"
        );
    }
    p_(0) = s[0];
    pCommitted_ = s[1];
}


std::string hydrostaticCavity::describe() const
{
    std::ostringstream os;
    os  << spec_.name << ": hydrostatic fluid, " << faces_.size()
        << " wetted faces, V_0 = " << spec_.initialVolume << ", K = "
        << spec_.bulkModulus << ", "
        << (volumeControlled() ? "volume control" : "pressure control");
    return os.str();
}

} // namespace form
