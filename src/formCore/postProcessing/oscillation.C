/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of oscillation.H: windowed mean, amplitude and frequency
    of a sampled signal (Turek & Hron 2006).
\*---------------------------------------------------------------------------*/
#include "oscillation.H"
#include <algorithm>
#include <cmath>

form::oscillation::oscillation(double t0, double t1)
:
    t0_(t0),
    t1_(t1)
{}


void form::oscillation::add(double t, double q)
{
    const double tol = 1e-9*std::max(std::abs(t), 1.0);
    if (t < t0_ - tol || t > t1_ + tol) return;
    if (t_.empty())
    {
        max_ = min_ = q;
    }
    else
    {
        max_ = std::max(max_, q);
        min_ = std::min(min_, q);
    }
    t_.push_back(t);
    q_.push_back(q);
}


std::vector<double> form::oscillation::crossings() const
{
    const double m = mean();
    std::vector<double> tau;
    for (std::size_t i = 1; i < t_.size(); ++i)
    {
        if (q_[i - 1] < m && q_[i] >= m)
        {
            const double w = (m - q_[i - 1])/(q_[i] - q_[i - 1]);
            tau.push_back(t_[i - 1] + w*(t_[i] - t_[i - 1]));
        }
    }
    return tau;
}


int form::oscillation::periods() const
{
    const std::vector<double> tau = crossings();
    return tau.size() < 2 ? 0 : int(tau.size()) - 1;
}


double form::oscillation::frequency() const
{
    const std::vector<double> tau = crossings();
    if (tau.size() < 2) return 0;
    return (tau.size() - 1)/(tau.back() - tau.front());
}
