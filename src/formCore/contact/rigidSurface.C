/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of rigidSurface.H: closest-point projections onto
    planes, spheres, cylinders, extruded, revolved, swept and path
    profiles (triangles: triangulatedSurface.C), and the tangent frame of
    a projection.
\*---------------------------------------------------------------------------*/
#include "rigidSurface.H"
#include "triangulatedSurface.H"
#include "formError.H"
#include <cmath>

namespace form
{

namespace
{

class plane : public rigidSurface
{
    vec3 p_, n_;
public:
    explicit plane(const surfaceInput& in)
    :
        p_(in.vector("point")),
        n_(in.direction("normal"))
    {}
    std::string type() const override { return "plane"; }
    surfaceProjection project(const vec3& y) const override
    {
        surfaceProjection P;
        P.gap = n_.dot(y - p_);
        P.normal = n_;
        return P;
    }
};


// Sphere (axis = zero) or cylinder: distance from a point or a line
class roundSurface : public rigidSurface
{
    vec3 c_;
    mat3 Pa_;       //!< projection onto the plane normal to the axis
    double R_;
    bool cylinder_;
public:
    roundSurface(const surfaceInput& in, bool cylinder)
    :
        c_(in.vector(cylinder ? "point" : "centre")),
        Pa_(mat3::Identity()),
        R_(in.positive("radius")),
        cylinder_(cylinder)
    {
        if (cylinder)
        {
            const vec3 a = in.direction("axis");
            Pa_ -= a*a.transpose();
        }
    }
    std::string type() const override
    {
        return cylinder_ ? "cylinder" : "sphere";
    }
    surfaceProjection project(const vec3& y) const override
    {
        surfaceProjection P;
        const vec3 d = Pa_*(y - c_);
        const double L = d.norm();
        P.gap = L - R_;
        if (L > 0)
        {
            P.normal = d/L;
            P.dNormalDY = (Pa_ - P.normal*P.normal.transpose())/L;
        }
        else
        {
            // at the centre (axis): any direction normal to the axis
            P.normal = Pa_.col(0).norm() > 0.5 ? vec3(Pa_.col(0).normalized())
                     : vec3(Pa_.col(1).normalized());
        }
        return P;
    }
};


//- A profile's projection in the plane of the unit directions e (its
//  first coordinate) and a (its second) as a surface's: n = [e a] n2,
//  dn/dy = [e a] dn2/dy2 [e a]^T (the turn of e itself is the caller's)
surfaceProjection lifted
(
    const profileProjection& q,
    const vec3& e,
    const vec3& a
)
{
    Eigen::Matrix<double, 3, 2> Bm;
    Bm.col(0) = e;
    Bm.col(1) = a;
    surfaceProjection P;
    P.gap = q.gap;
    P.normal = Bm*q.normal;
    P.dNormalDY = Bm*q.dNormalDY*Bm.transpose();
    return P;
}


class extrudedProfile : public rigidSurface
{
    std::shared_ptr<rigidProfile> profile_;
    vec3 o_;
    Eigen::Matrix<double, 3, 2> Q_;
public:
    explicit extrudedProfile(const surfaceInput& in)
    :
        profile_(in.profile),
        o_(in.vector("origin"))
    {
        if (!profile_)
        {
            throw inputError("profile", "extrudedProfile needs a profile");
        }
        const vec3 u = in.direction("xAxis");
        vec3 v = in.direction("yAxis");
        v -= u*u.dot(v);
        if (!(v.norm() > 1e-6))
        {
            throw inputError("yAxis", "yAxis is parallel to xAxis");
        }
        Q_.col(0) = u;
        Q_.col(1) = v.normalized();
    }
    std::string type() const override { return "extrudedProfile"; }
    surfaceProjection project(const vec3& y) const override
    {
        const profileProjection q =
            profile_->project(Q_.transpose()*(y - o_));
        surfaceProjection P;
        P.gap = q.gap;
        P.normal = Q_*q.normal;
        P.dNormalDY = Q_*q.dNormalDY*Q_.transpose();
        return P;
    }
};


//- A profile in the (r, z) half-plane swept around a rectangular core
//  (revolved about the axis when the core is a point: rigidSurface.H)
class sweptProfile : public rigidSurface
{
    std::shared_ptr<rigidProfile> profile_;
    vec3 o_, a_, e1_, e2_;
    double A_, B_;
    bool revolved_;
public:
    sweptProfile(const surfaceInput& in, bool revolved)
    :
        profile_(in.profile),
        o_(in.vector("origin")),
        a_(in.direction("axis")),
        A_(0),
        B_(0),
        revolved_(revolved)
    {
        if (!profile_)
        {
            throw inputError("profile", type() + " needs a profile");
        }
        const vec3 trial = revolved
          ? (std::abs(a_(0)) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0))
          : in.direction("xAxis");
        const vec3 w = trial - a_*a_.dot(trial);
        if (!(w.norm() > 1e-6))
        {
            throw inputError("xAxis", "entry 'xAxis' is parallel to 'axis'");
        }
        e1_ = w.normalized();
        e2_ = a_.cross(e1_);
        if (!revolved)
        {
            A_ = in.nonNegative("coreX");
            B_ = in.nonNegative("coreY");
        }
    }
    std::string type() const override
    {
        return revolved_ ? "revolvedProfile" : "sweptProfile";
    }
    surfaceProjection project(const vec3& y) const override
    {
        const vec3 d = y - o_;
        const double z = a_.dot(d);
        // The closest point of the core in the plane normal to the axis
        const double x1 = e1_.dot(d), x2 = e2_.dot(d);
        const double c1 = std::max(-A_, std::min(A_, x1));
        const double c2 = std::max(-B_, std::min(B_, x2));
        const vec3 radial = (x1 - c1)*e1_ + (x2 - c2)*e2_;
        const double r = radial.norm();
        const double size = 1 + d.norm();
        // radial direction; on the core any normal to the axis
        const vec3 er = r > 1e-12*size ? vec3(radial/r) : e1_;
        const vec3 et = a_.cross(er);
        const profileProjection q = profile_->project(Eigen::Vector2d(r, z));
        surfaceProjection P = lifted(q, er, a_);
        // e_r turns about the axis where the core's closest point is a
        // corner (or the point core): de_r/dy = e_t e_t^T/r; along a side
        // it is constant. n_r/r has the limit dn_r/dr on the axis.
        const bool corner =
            std::abs(x1) >= A_ && std::abs(x2) >= B_;
        if (corner)
        {
            const double nrOverR =
                r > 1e-12*size ? q.normal(0)/r : q.dNormalDY(0, 0);
            P.dNormalDY += nrOverR*et*et.transpose();
        }
        return P;
    }
};


//- A profile in the (s, z) plane swept along a planar path
//  (rigidSurface.H: pathProfile)
class pathProfile : public rigidSurface
{
    std::shared_ptr<rigidProfile> profile_, path_;
    vec3 o_, a_;
    Eigen::Matrix<double, 3, 2> E_;     //!< [e1 e2]: the path's plane
public:
    explicit pathProfile(const surfaceInput& in)
    :
        profile_(in.profile),
        path_(in.path),
        o_(in.vector("origin")),
        a_(in.direction("axis"))
    {
        if (!profile_)
        {
            throw inputError("profile", "pathProfile needs a profile");
        }
        if (!path_)
        {
            throw inputError
            (
                "path", "pathProfile needs a path (points in the plane"
                " normal to the axis)"
            );
        }
        const vec3 trial = in.direction("xAxis");
        const vec3 w = trial - a_*a_.dot(trial);
        if (!(w.norm() > 1e-6))
        {
            throw inputError("xAxis", "entry 'xAxis' is parallel to 'axis'");
        }
        E_.col(0) = w.normalized();
        E_.col(1) = a_.cross(E_.col(0));
    }
    std::string type() const override { return "pathProfile"; }
    surfaceProjection project(const vec3& y) const override
    {
        const vec3 d = y - o_;
        const profileProjection p = path_->project(E_.transpose()*d);
        if (p.vertex)
        {
            throw numericalError
            (
                "pathProfile: the point (" + std::to_string(y(0)) + " "
              + std::to_string(y(1)) + " " + std::to_string(y(2))
              + ") lies beyond an end of the tool's path or at a sharp"
                " corner of it: extend the path beyond the sheet and give"
                " every interior path point a fillet radius (pathRadii)"
            );
        }
        // s = -g_path (left of the path), m = ds/dy its left normal
        const vec3 m = -(E_*p.normal);
        const profileProjection q =
            profile_->project(Eigen::Vector2d(-p.gap, a_.dot(d)));
        surfaceProjection P = lifted(q, m, a_);
        P.dNormalDY -= q.normal(0)*(E_*p.dNormalDY*E_.transpose());
        return P;
    }
};

const bool registered = []()
{
    auto& reg = rigidSurface::registry();
    reg["plane"] = [](const surfaceInput& in)
    {
        return std::unique_ptr<rigidSurface>(new plane(in));
    };
    reg["sphere"] = [](const surfaceInput& in)
    {
        return std::unique_ptr<rigidSurface>(new roundSurface(in, false));
    };
    reg["triSurface"] = newTriangulatedSurface;
    reg["cylinder"] = [](const surfaceInput& in)
    {
        return std::unique_ptr<rigidSurface>(new roundSurface(in, true));
    };
    reg["extrudedProfile"] = [](const surfaceInput& in)
    {
        return std::unique_ptr<rigidSurface>(new extrudedProfile(in));
    };
    reg["revolvedProfile"] = [](const surfaceInput& in)
    {
        return std::unique_ptr<rigidSurface>(new sweptProfile(in, true));
    };
    reg["sweptProfile"] = [](const surfaceInput& in)
    {
        return std::unique_ptr<rigidSurface>(new sweptProfile(in, false));
    };
    reg["pathProfile"] = [](const surfaceInput& in)
    {
        return std::unique_ptr<rigidSurface>(new pathProfile(in));
    };
    return true;
}();

} // anonymous namespace


vec3 surfaceInput::vector(const std::string& name) const
{
    const auto it = vectors.find(name);
    if (it == vectors.end())
    {
        throw inputError(name, "missing entry '" + name + "'");
    }
    if (!it->second.allFinite())
    {
        throw inputError(name, "entry '" + name + "' is not finite");
    }
    return it->second;
}


vec3 surfaceInput::direction(const std::string& name) const
{
    const vec3 v = vector(name);
    if (!(v.norm() > 0))
    {
        throw inputError(name, "entry '" + name + "' is not a direction (zero)");
    }
    return v.normalized();
}


double surfaceInput::nonNegative(const std::string& name) const
{
    const auto it = scalars.find(name);
    if (it == scalars.end())
    {
        throw inputError(name, "missing entry '" + name + "'");
    }
    if (!(it->second >= 0) || !std::isfinite(it->second))
    {
        throw inputError
        (
            name, "entry '" + name + "' = " + std::to_string(it->second)
          + " must be zero or positive"
        );
    }
    return it->second;
}


double surfaceInput::positive(const std::string& name) const
{
    const auto it = scalars.find(name);
    if (it == scalars.end())
    {
        throw inputError(name, "missing entry '" + name + "'");
    }
    if (!(it->second > 0) || !std::isfinite(it->second))
    {
        throw inputError
        (
            name, "entry '" + name + "' = " + std::to_string(it->second)
          + " must be positive"
        );
    }
    return it->second;
}


std::map<std::string, rigidSurface::factoryFn>& rigidSurface::registry()
{
    static std::map<std::string, factoryFn> table;
    return table;
}


std::string rigidSurface::validTypes()
{
    (void)registered;
    std::string names;
    for (const auto& e : registry())
    {
        names += (names.empty() ? "" : " ") + e.first;
    }
    return names;
}


std::unique_ptr<rigidSurface> rigidSurface::New
(
    const std::string& type,
    std::map<std::string, vec3> vectors,
    std::map<std::string, double> scalars,
    std::shared_ptr<rigidProfile> profile,
    std::shared_ptr<const triangulation> triangles,
    std::shared_ptr<rigidProfile> path
)
{
    (void)registered;
    const auto it = registry().find(type);
    if (it == registry().end())
    {
        throw inputError
        (
            "type",
            "unknown surface type '" + type + "'; valid: " + validTypes()
        );
    }
    surfaceInput in
    {
        std::move(vectors), std::move(scalars), std::move(profile),
        std::move(triangles), std::move(path)
    };
    return it->second(in);
}


tangentFrame tangentFrame::of(const surfaceProjection& P, const vec3& ref)
{
    tangentFrame F;
    const vec3& n = P.normal;
    const vec3 w = ref - n*n.dot(ref);
    const double L = w.norm();
    if (!(L > 1e-8*ref.norm()))
    {
        throw numericalError
        (
            "tangentFrame: the reference direction is parallel to the normal"
        );
    }
    F.t1 = w/L;
    F.t2 = n.cross(F.t1);
    derivatives(n, ref, F.t1, L, P.dNormalDY, F.dT1DY, F.dT2DY);
    return F;
}

} // namespace form
