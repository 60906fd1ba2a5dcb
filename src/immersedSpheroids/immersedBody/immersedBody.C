/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBody.H"
#include "cellSolidFraction.H"
#include "dictionaryChecks.H"
#include "treeDataCell.H"
#include "indexedOctree.H"
#include "mathematicalConstants.H"
#include "coreConversions.H"
#include "diagTensor.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The rotation taking the x axis to the direction d (shortest arc)
quaternion axisToQuaternion(const vector& d)
{
    const vector ex(1, 0, 0);
    const vector n = d/mag(d);
    const scalar c = ex & n;
    if (c < -1 + 1e-12)
    {
        // antiparallel: half a turn about z
        return quaternion(0, vector(0, 0, 1));
    }
    // q = (1 + c, ex ^ n) normalised: half the angle between ex and n
    quaternion q(1 + c, ex ^ n);
    q.normalize();
    return q;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::immersedBody::immersedBody(const word& name, const dictionary& dict)
:
    name_(name),
    semiAxes_(Zero),
    density_(0)
{
    using namespace immersedSpheroids;

    checkKeywords
    (
        dict,
        wordList
        ({
            "semiAxes", "density", "centre", "orientation", "axis",
            "velocity", "angularVelocity", "motion"
        })
    );

    semiAxes_ = readChecked<vector>
    (
        dict, "semiAxes", "the semi-axes (a b c) along the body x, y, z axes [m], each > 0"
    );
    if (cmptMin(semiAxes_) <= 0)
    {
        entryError
        (
            dict, "semiAxes",
            "every semi-axis must be > 0 (got " + Foam::name(semiAxes_) + ")"
        );
    }
    density_ = readPositive(dict, "density", "the body density [kg/m^3], > 0");

    state_.centre = readChecked<point>(dict, "centre", "the centre (x y z) [m]");

    if (dict.found("orientation") && dict.found("axis"))
    {
        entryError
        (
            dict, "axis",
            "give either orientation (a unit quaternion (w x y z)) or axis"
            " (the direction of the body x axis), not both"
        );
    }
    if (dict.found("orientation"))
    {
        const FixedList<scalar, 4> q = readChecked<FixedList<scalar, 4>>
        (
            dict, "orientation", "a unit quaternion (w x y z), body to world"
        );
        // four significant digits make a unit quaternion to 1e-4; it is
        // normalised after the check
        const scalar tolerance = 1e-4;
        const scalar norm =
            Foam::sqrt(sqr(q[0]) + sqr(q[1]) + sqr(q[2]) + sqr(q[3]));
        if (mag(norm - 1) > tolerance)
        {
            entryError
            (
                dict, "orientation",
                "a unit quaternion (w x y z) is required: |q| = "
              + Foam::name(norm) + " differs from 1 by more than "
              + Foam::name(tolerance) + " (give the components to at least"
                " four significant digits, e.g. (0.7071 0 0 0.7071))"
            );
        }
        state_.orientation = listToQuaternion(q);
        state_.orientation.normalize();
    }
    else if (dict.found("axis"))
    {
        const vector d = readChecked<vector>
        (
            dict, "axis", "the direction (x y z) of the body x axis, non-zero"
        );
        if (mag(d) < VSMALL)
        {
            entryError(dict, "axis", "the axis direction must be non-zero");
        }
        state_.orientation = axisToQuaternion(d);
    }

    state_.velocity = readCheckedOrDefault<vector>
    (
        dict, "velocity", Zero, "the initial velocity (x y z) [m/s]"
    );
    state_.angularVelocity = readCheckedOrDefault<vector>
    (
        dict, "angularVelocity", Zero,
        "the initial angular velocity (x y z), world frame [rad/s]"
    );

    if (!dict.isDict("motion"))
    {
        entryError
        (
            dict, "motion",
            "a motion sub-dictionary { type <fixed|prescribed|free|"
            "freeTranslation|freeRotation>; } is required"
        );
    }
    motion_ = bodyMotion::New(dict.subDict("motion"));
}


Foam::immersedBody::immersedBody
(
    const word& name,
    const vector& semiAxes,
    const scalar density,
    const bodyState& state,
    const dictionary& motionDict
)
:
    name_(name),
    semiAxes_(semiAxes),
    density_(density),
    motion_(bodyMotion::New(motionDict)),
    state_(state)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::immersedBody::volume() const
{
    return collision::ellipsoidVolume(immersedSpheroids::toCore(semiAxes_));
}


Foam::scalar Foam::immersedBody::mass() const
{
    return density_*volume();
}


Foam::vector Foam::immersedBody::bodyInertia() const
{
    return immersedSpheroids::toFoam
    (
        collision::ellipsoidInertia(immersedSpheroids::toCore(semiAxes_), mass())
    );
}


Foam::symmTensor Foam::immersedBody::quadraticForm() const
{
    const tensor R = state_.R();
    const diagTensor D
    (
        1/sqr(semiAxes_.x()), 1/sqr(semiAxes_.y()), 1/sqr(semiAxes_.z())
    );
    return symm(R & D & R.T());
}


const Foam::vector& Foam::immersedBody::tangentialArea() const
{
    if (tangentialArea_.x() < 0)
    {
        // midpoint rule on x = (a s cos phi, b s sin phi, c u), s = sqrt(1 -
        // u^2): dS = sqrt(b^2 c^2 s^2 cos^2 + a^2 c^2 s^2 sin^2 + a^2 b^2 u^2)
        // du dphi, smooth at the poles; 48 x 96 points give the integrals to
        // about 1e-3, enough for a stabilisation
        const scalar a = semiAxes_.x(), b = semiAxes_.y(), c = semiAxes_.z();
        const label nu = 48, nphi = 96;
        const scalar du = 2.0/nu;
        const scalar dphi = constant::mathematical::twoPi/nphi;
        tangentialArea_ = Zero;
        tangentialMoment_ = Zero;
        for (label i = 0; i < nu; ++i)
        {
            const scalar u = -1 + (i + 0.5)*du;
            const scalar sn = Foam::sqrt(1 - u*u);
            for (label j = 0; j < nphi; ++j)
            {
                const scalar phi = (j + 0.5)*dphi;
                const scalar cp = Foam::cos(phi), sp = Foam::sin(phi);
                const vector x(a*sn*cp, b*sn*sp, c*u);
                const scalar dS =
                    Foam::sqrt
                    (
                        sqr(b*c*sn*cp) + sqr(a*c*sn*sp) + sqr(a*b*u)
                    )*du*dphi;
                vector n(x.x()/sqr(a), x.y()/sqr(b), x.z()/sqr(c));
                n /= mag(n);
                for (direction k = 0; k < 3; ++k)
                {
                    vector e(Zero);
                    e[k] = 1;
                    tangentialArea_[k] += (1 - sqr(n[k]))*dS;
                    const vector v = e ^ x;
                    tangentialMoment_[k] += (magSqr(v) - sqr(v & n))*dS;
                }
            }
        }
    }
    return tangentialArea_;
}


const Foam::vector& Foam::immersedBody::tangentialMoment() const
{
    tangentialArea();
    return tangentialMoment_;
}


Foam::boundBox Foam::immersedBody::bounds() const
{
    // support function of the ellipsoid along e_i: sqrt(e_i^T P e_i),
    // P = R diag(a^2, b^2, c^2) R^T
    const tensor R = state_.R();
    const diagTensor D(sqr(semiAxes_.x()), sqr(semiAxes_.y()), sqr(semiAxes_.z()));
    const tensor P = R & D & R.T();
    const vector h(Foam::sqrt(P.xx()), Foam::sqrt(P.yy()), Foam::sqrt(P.zz()));
    return boundBox(state_.centre - h, state_.centre + h);
}


Foam::point Foam::immersedBody::supportPoint(const vector& n) const
{
    // x = c + P n/sqrt(n^T P n), P = R diag(a^2, b^2, c^2) R^T
    const tensor R = state_.R();
    const diagTensor D(sqr(semiAxes_.x()), sqr(semiAxes_.y()), sqr(semiAxes_.z()));
    const vector Pn = (R & D & R.T()) & n;
    return state_.centre + Pn/Foam::sqrt(n & Pn);
}


void Foam::immersedBody::updateCells
(
    const polyMesh& mesh,
    const indexedOctree<treeDataCell>& cellTree,
    const scalarField& cellRadius,
    const periodicDomain& domain,
    const scalar linkReach
)
{
    cells_.clear();
    fractions_.clear();
    cellImages_.clear();

    const boundBox bb = bounds();
    for (direction d = 0; d < 3; ++d)
    {
        // an image would overlap the body itself (a cell covered twice)
        if (domain.periodic(d) && !(bb.span()[d] < domain.period(d)))
        {
            FatalErrorInFunction
                << "Body '" << name_ << "' spans " << bb.span()[d] << " along "
                << vector::componentNames[d] << ", not less than the period "
                << domain.period(d) << " of the periodic patch '"
                << domain.patchName(d) << "': it would overlap its own image."
                << " Use a larger box (or a smaller body)" << nl
                << exit(FatalError);
        }
    }
    domain.images(bb, linkReach, images_);

    const symmTensor A = quadraticForm();
    const scalar lipschitz = 1/minSemiAxis();
    const pointField& C = mesh.cellCentres();

    // this rank's own cells only: an image outside the bounds of its cell
    // tree (the rank's sub-domain) is skipped before any search
    const treeBoundBox& localBounds = cellTree.bb();
    forAll(images_, imagei)
    {
        const vector& shift = images_[imagei];
        const boundBox imageBox(bb.min() + shift, bb.max() + shift);
        if (!imageBox.overlaps(localBounds))
        {
            continue;
        }
        const point X = state_.centre + shift;
        const labelList candidates = cellTree.findBox(treeBoundBox(imageBox));
        for (const label celli : candidates)
        {
            // |psi(x) - psi(C)| <= |x - C|/a_min: far cells need no clipping
            const scalar psi = levelSet(C[celli], X, A);
            const scalar reach = lipschitz*cellRadius[celli];
            scalar alpha;
            if (psi >= reach)
            {
                continue;
            }
            else if (psi <= -reach)
            {
                alpha = 1;
            }
            else
            {
                alpha = immersedSpheroids::cellSolidFraction(mesh, celli, X, A);
                if (alpha <= 0)
                {
                    continue;
                }
            }
            cells_.append(celli);
            fractions_.append(alpha);
            cellImages_.append(imagei);
        }
    }
}


void Foam::immersedBody::wrapCentre(const periodicDomain& domain)
{
    const point wrapped = domain.wrap(state_.centre);
    unwrapShift_ += state_.centre - wrapped;
    state_.centre = wrapped;
}


void Foam::immersedBody::writeState(Ostream& os) const
{
    state_.write(os);
    os.writeEntry("hydroForce", hydroForce_);
    os.writeEntry("hydroTorque", hydroTorque_);
    os.writeEntry("collisionForce", collisionForce_);
    os.writeEntry("collisionTorque", collisionTorque_);
    os.writeEntry("nFluidMomenta", nFluidMomenta_);
    os.writeEntry("fluidMomentum", fluidMomentum_);
    os.writeEntry("fluidAngularMomentum", fluidAngularMomentum_);
    os.writeEntry("fluidMomentum0", fluidMomentum0_);
    os.writeEntry("fluidAngularMomentum0", fluidAngularMomentum0_);
    os.writeEntry("acceleration", acceleration_);
    os.writeEntry("angularAcceleration", angularAcceleration_);
    os.writeEntry("velocityIncrement", velocityIncrement_);
    os.writeEntry("angularVelocityIncrement", angularVelocityIncrement_);
    os.writeEntry("unwrapShift", unwrapShift_);
}


void Foam::immersedBody::readState(const dictionary& dict)
{
    using namespace immersedSpheroids;

    const string vec("a vector (x y z)");
    state_.centre = readChecked<point>(dict, "centre", vec);
    state_.velocity = readChecked<vector>(dict, "velocity", vec);
    state_.orientation = listToQuaternion
    (
        readChecked<FixedList<scalar, 4>>(dict, "orientation", "a quaternion (w x y z)")
    );
    state_.angularVelocity = readChecked<vector>(dict, "angularVelocity", vec);
    hydroForce_ = readCheckedOrDefault<vector>(dict, "hydroForce", Zero, vec);
    hydroTorque_ = readCheckedOrDefault<vector>(dict, "hydroTorque", Zero, vec);
    collisionForce_ = readCheckedOrDefault<vector>(dict, "collisionForce", Zero, vec);
    collisionTorque_ = readCheckedOrDefault<vector>(dict, "collisionTorque", Zero, vec);
    nFluidMomenta_ = readCheckedOrDefault<label>
    (
        dict, "nFluidMomenta", 0, "0, 1 or 2 (internal-fluid momenta known)"
    );
    fluidMomentum_ = readCheckedOrDefault<vector>(dict, "fluidMomentum", Zero, vec);
    fluidAngularMomentum_ =
        readCheckedOrDefault<vector>(dict, "fluidAngularMomentum", Zero, vec);
    fluidMomentum0_ = readCheckedOrDefault<vector>(dict, "fluidMomentum0", Zero, vec);
    fluidAngularMomentum0_ =
        readCheckedOrDefault<vector>(dict, "fluidAngularMomentum0", Zero, vec);
    acceleration_ = readCheckedOrDefault<vector>(dict, "acceleration", Zero, vec);
    angularAcceleration_ =
        readCheckedOrDefault<vector>(dict, "angularAcceleration", Zero, vec);
    velocityIncrement_ =
        readCheckedOrDefault<vector>(dict, "velocityIncrement", Zero, vec);
    angularVelocityIncrement_ =
        readCheckedOrDefault<vector>(dict, "angularVelocityIncrement", Zero, vec);
    unwrapShift_ = readCheckedOrDefault<vector>
    (
        dict, "unwrapShift", Zero,
        "a vector (x y z): the whole periods the centre was moved by"
    );
}


// ************************************************************************* //
