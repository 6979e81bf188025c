// Joins across the banks of one occluder (private, case 1 of §5.1 for wide
// pieces): a strand lying over the back hair or the cap cuts it into pieces
// whose cut edges face each other across the strand.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "context.h"

namespace hair25d::completion::detail {

// A join is considered across the banks of an occluder when at least this
// share of the rays from each edge lands next to the other edge.
inline constexpr double kMinBankShare = 0.5;
// A ray across the occluders goes on through this many pixels of label 0
// between two hair regions: the light, anti-aliased rim of a drawn line that
// the outline assignment leaves unlabelled (only dark pixels are assigned).
// Longer runs are the face or the paper, where a ray stops.
inline constexpr double kMaxOutlineGap = 3.0;
// Its cost: base + weight × (1 − share) (+ the colour term of strand joins),
// so that a clear bank join (share ≈ 1) ranks with good strand joins.
inline constexpr double kBankBaseCost = 0.5;
inline constexpr double kBankShareWeight = 2.0;

// Largest median RGB step across the cut. Pieces of one strand meet the
// occluder in the same colour (flat, cel band, gradient and tone continue
// under a strand); chosen on generated seeds 101-116 of the four shadings,
// where the right joins stepped 0-8.4 (one 19.5, one 58.8) and the wrong
// ones 11.9-163; the annotated cases make no region-level join either way.
inline constexpr double kMaxMassColourStep = 10.0;

// Or the pieces are painted by one linear field (RegionFields::step, RGB;
// the body joins' limit too): a gradient over the whole back hair steps
// across the fan by its slope times the crossed width (gradient seeds
// 101-116, the field without its gates: right candidates 0-0.75 (two 1.75,
// 2.13), wrong ones 1.45 and up).
inline constexpr double kMaxMassFieldStep = 1.0;
// Two pieces whose own paint is linear and whose joint field (a gradient)
// misses them by more than this are painted by two gradients, two strands,
// though the windows at the cuts step little (session 13: the chosen mass
// joins of gradient 201-216 and 301-316, right ones 0-0.88 where the field
// says something, wrong ones 0.90, 9.0, 9.3, 24.1; at 3 or 6, gradient
// 201-216 0.959 / 0.704 -> 0.970 / 0.704, 301-316 0.881 / 0.831 -> 0.894 /
// 0.834, 101-116 unchanged; at 1.5 101-116 0.979 / 0.852 -> 0.979 / 0.841).
// The mass joins, and since session 16 the face joins, refuse such pairs.
inline constexpr double kMinOtherFieldStep = 3.0;

// On a cel drawing the two pieces' flat paint (RegionCels::step) must step
// at most this much (the body joins' limit too): pieces of one strand share
// one paint; the generator varies each strand's colour a little, and a bang
// or an "under" strand lying on the face in nearly the back hair's paint
// lies between the judgement's `same` (1 RGB) and `other` (3 RGB) limits
// (session 14, dev seeds 2000-2099: the chosen mass joins of cel drawings,
// right ones 0-0.58, wrong ones 0, 1.0, 1.41, 1.41, 1.46, 1.73, 2.45, 3.0).
inline constexpr double kMaxMassCelStep = 1.0;

// Per RGB of texture spread in the windows (the two windows' RGB standard
// deviations summed) beyond kTextureFloor, the step may be this much larger:
// an 11 x 11 window's mean over screentone dots moves with the dots' phase,
// so one tone measures 10-35 RGB apart on the two sides of a strand. On
// generated seeds 101-116 screentone windows spread 250-340 and the right
// candidates stepped 12-35 (wrong ones 78-240); flat, cel and gradient
// windows spread 0-50, the annotated cases' 19-65 (line rims, shading
// strokes) — there a looser step joined a wrong pair (case1 8-14: 11.6 RGB,
// spread 45), so below the floor the tolerance stays kMaxMassColourStep.
inline constexpr double kMassSpreadShare = 0.1;
inline constexpr double kTextureFloor = 60.0;

// A ray from an edge pixel across the occluders: its index along the edge,
// start (on the edge) and end (on the far bank).
using BankRay = std::tuple<int, Vec2, Vec2>;

struct BankCrossings {
  int rays = 0;
  std::map<int, std::vector<BankRay>> hits;  // landed region -> rays that reached it
  double depth = 0.0;   // mean distance the piece reaches behind the edge, inwards
  double window = 0.0;  // share of the rays whose inward run ends under an occluder of the piece
};

// Rays from every other pixel of `edge` along the outline's outward normal,
// through regions above the edge's region only, up to 0.6 edge lengths: a
// ray that then reaches a region which all crossed regions lie above as well
// lands on the far bank.
BankCrossings cross_occluders(const Context& ctx, const Edge& edge);

// Runs of consecutive rays (index along the outline within 4) as closed
// polygons: starts, then ends back.
std::vector<Polyline> ray_bands(const std::vector<BankRay>& rays);

// Where a ray leaves region `id` at pixel `contour[i]` of its outline: the
// pixel's centre and the outward unit normal (across the chord from the
// point 3 before to the point 3 after, turned away from the region); none
// where that chord is shorter than a pixel.
std::optional<std::pair<Vec2, Vec2>> outward_ray(const Context& ctx,
                                                 const std::vector<cv::Point>& contour, int i,
                                                 int id);

struct BankJoin {
  double share = 0.0;  // min over both edges of the share of rays landing next to the other
  std::vector<Polyline> bands;  // the hidden part: runs of consecutive rays from a
  bool window = false;          // a piece passed as a window, not by its depth (bank_crossings.cpp)
};

// The bank join of edges a and b (their crossings ca, cb). Zero share when
// either piece is thinner behind its edge than 1.5 × the width crossed: a
// strand piece lying on the back hair faces the back hair across an
// occluder too, but it is no wide piece cut in two.
BankJoin bank_join(const BankCrossings& ca, const BankCrossings& cb, const Edge& a, const Edge& b);

}  // namespace hair25d::completion::detail

namespace hair25d::completion::detail {

// Back hair seen between the strands lying over it and around the face: a
// wide piece under a fan of overlapping strands faces its other pieces
// across several occluders at once, so no single edge pair is a case-1 or
// bank candidate. Region level: rays from every outline pixel of a piece
// that lies above no region (or above tails only: lowest regions that only
// such pieces cover), along the outward normal, through regions above it,
// landing on another such piece that all crossed regions lie above as
// well. (The face is left to the face joins: rays across it also
// land on bangs lying on the face, which lie above no region either.)
struct MassJoin {
  int region_a = 0, region_b = 0;
  int rays = 0;                 // the fewer of the rays landing a -> b and b -> a
  double colour = 0.0;          // median RGB step across the cut (the larger way)
  std::vector<Polyline> bands;  // the hidden part: runs of consecutive landing rays
};
// The join of `a` and `b` whose hidden part is the bands of `landing`, the
// rays from a that land on b (any ray with index, from and to).
template <class Ray>
MassJoin mass_join(int a, int b, int rays, double colour, const std::vector<Ray>& landing) {
  std::vector<BankRay> band_rays;
  band_rays.reserve(landing.size());
  for (const Ray& r : landing) band_rays.emplace_back(r.index, r.from, r.to);
  return MassJoin{a, b, rays, colour, ray_bands(band_rays)};
}
// Most rays first: the candidates' order when their rays are counted.
void sort_by_rays(std::vector<MassJoin>& joins);
// Screentone (the generator's, and manga's): ink dots cover a share of a
// strand's pixels that is the same all along the strand, so pieces of one
// strand share it and the paper colour between the dots; a window's mean
// colour moves with the dots' phase. Per region, the share of pixels 2 px
// inside it darker than Options::dark_luma, computed once.
class RegionTones {
 public:
  // Both regions with at least this dark share are textured (the
  // generator's tones cover 0.12-0.55 of a strand; flat, cel and gradient
  // fills of hair lighter than dark_luma 0). Hair darker than dark_luma all
  // over counts too: its pieces share the tone 1 and the light percentile
  // is its colour.
  static constexpr double kMinTone = 0.05;
  // Largest tone step between textured pieces of one strand: on generated
  // screentone seeds 101-116 path candidates of one strand stepped 0-0.016
  // (a few pieces with drawn lines inside 0.07-0.32), of two 0-0.27, mostly
  // over 0.05.
  static constexpr double kMaxToneStep = 0.02;
  // A dot: a dark component of at most this many pixels (the generator's
  // dots cover 3-35 px at 800 x 640; drawn lines are longer).
  static constexpr int kMaxDotArea = 60;
  // A region shows dots (counts towards a screentone drawing) with at least
  // this many whole dots.
  static constexpr int kMinDots = 3;
  // Its dot mass is measured over at least this many: a small piece of a
  // strand (a bang's end under another bang, a cap sliver) holds one or two
  // whole dots, and each has the strand's ink (session 10: with 3, 58 of
  // the 104 missed same-strand pairs of screentone 101-116 had a piece
  // without a mass; with 1, precision 0.943 -> 0.950 at the same recall).
  static constexpr int kMinMassDots = 1;
  // Pieces of one tone: dot masses within this share of the larger and
  // dark shares within kMaxSameToneStep. On generated screentone seeds
  // 101-116 strand-join candidates of one strand with both masses measured
  // differed by 0-0.04 (151 edge pairs, dark shares 0-0.032 apart), of two
  // strands mostly by more than 0.08 (22 of 478 within 0.04).
  static constexpr double kMaxSameMassStep = 0.04;
  static constexpr double kMaxSameToneStep = 0.04;
  // Pieces of two tones: masses more than this share apart, or dark shares
  // more than kMinOtherToneStep apart (none of one strand on 101-116).
  static constexpr double kMinOtherMassStep = 0.08;
  // Pieces of one tone by their cell masses (a piece without a whole dot):
  // within this share. On generated screentone seeds 101-116 17 of the 37
  // such pairs of one strand stepped at most 0.015, and 5 pairs of two
  // strands (0.02: 18 and 7).
  static constexpr double kMaxSameCellStep = 0.015;
  static constexpr double kMinOtherToneStep = 0.08;
  // The dark shares' step says two tones only when both pieces hold at
  // least this many whole dots (session 18: dev screentone 2078's back
  // piece 28, 721 px and one whole dot, stepped 0.09 from its strand's
  // other pieces while the dot masses agreed within 6.3 %; 4 and 10 measured
  // the same on dev 2000-2099 and 3000-3099).
  static constexpr int kMinShareDots = 4;
  // A piece with a dark share under this is paper-white (a third of the
  // generator's strands carry no tone).
  static constexpr double kPaperWhite = 0.01;

  enum class Match { kUnknown, kSame, kOther };

  explicit RegionTones(const Context& ctx) : ctx_(&ctx) {}
  double tone(int region);
  // How many pixels the dark share was measured over (2 px inside the
  // region): a sliver has few, and no dot need fall on them.
  int tone_pixels(int region);
  // The drawing's dot lattice period (px), 0 without a lattice (too few
  // whole dots).
  double dot_period();
  // False when both are textured and their tones differ by more than
  // kMaxToneStep; `textured` says whether both are.
  bool same_tone(int a, int b, bool* textured);
  // The median ink of the region's whole dots (dark components of at most
  // kMaxDotArea px, 1 px clear of its border, with their anti-aliased rim:
  // darkness summed from the region's paper, its 90th luma percentile, to
  // its darkest pixel), or -1 with fewer than kMinMassDots. Unlike the dark
  // share, which moves with the dots' phase against the pixel grid and
  // with how many dots a small piece cuts, a dot's ink is the same
  // wherever it lies; with the dark share it also fixes the dots' period.
  double dot_mass(int region);
  // The ink of one dot weighed on the drawing's dot lattice (`lattice`):
  // pi r^2 for the radius r at which the region's radial profile (the mean
  // darkness of its pixels 2 px inside it against their distance from the
  // nearest lattice point) falls through one half; -1 without a lattice, on
  // a region whose dots do not lie on it, or with too few pixels. A dot cut
  // by the region's border still shows its profile, so a sliver between
  // strands (every dot cut) or a dense tone (dots touching: no whole dot)
  // is weighed as well.
  double cell_mass(int region);
  // The dot mass of a region's whole dots (`dot_mass`), or -1 where those
  // "dots" are dots run together: a dense tone's dots touch through their
  // anti-aliased rims, and a pair or a chain of them passes for one small
  // dark component; its mass is then over kMaxMergedDotRatio times the cell
  // mass (the ink of one dot weighed on the lattice). Session 18, dev
  // screentone 2000-2099 and 3000-3099: 11 of the 3669 regions with both
  // masses (dark shares 0.43-0.57: dense back hair and its pieces) measured
  // 2.09-3.28 times their cell mass, every other one at most 1.28 times.
  double whole_dot_mass(int region);
  static constexpr double kMaxMergedDotRatio = 1.5;
  // The step between two pieces' masses (a share of the larger): their
  // whole dots' masses (`whole_dot_mass`), else (a piece without a whole
  // dot) their cell masses, else infinity.
  double mass_step(int a, int b);
  // The drawing is screentone: a quarter of the regions or more show whole
  // dots (on generated screentone drawings 8-18 of 24-34 regions, on
  // flat, two-tone, gradient and the annotated cases none).
  bool screentone();
  // kSame / kOther when both pieces' dots are measured and agree / differ
  // (above); kUnknown otherwise or on a drawing that is no screentone.
  Match match(int a, int b);
  // kOther, and sure of it: both pieces hold kMinShareDots whole dots, or
  // their cell masses do not agree within kMinOtherMassStep either (a piece
  // with one to three whole dots is weighed by those alone: dev screentone
  // 5003's piece 20 and 5075's 30, one dot each, stepped 9.5 % and 9.3 %
  // from their strands' other pieces, whose cell masses agreed within
  // 0.5 % and 1.9 %).
  bool two_tones(int a, int b);

 private:
  // The drawing's square dot lattice, fitted to the whole dots' centres
  // (the generator's is one for the drawing): its period (px) and angle
  // (rad, modulo 90°); invalid with too few dots. Its phase is read near
  // each region (cell_mass).
  struct Lattice {
    bool valid = false;
    double period = 0.0, angle = 0.0;
  };
  const Lattice& lattice();
  // A region's dots must show the lattice's phase this strongly (the
  // darkness-weighted mean resultant of its pixels' lattice coordinates).
  static constexpr double kMinPhaseStrength = 0.2;
  // The phase is read from the pixels within this many periods of a region.
  static constexpr double kPhaseReach = 6.0;
  // The radial profile's bins (px) and the fewest pixels a bin inside the
  // radius needs.
  static constexpr double kProfileBin = 0.25;
  static constexpr int kMinProfilePixels = 3;

  const Context* ctx_;
  std::map<int, double> tones_, masses_, cells_;
  std::map<int, int> tone_pixels_;  // with tones_
  std::map<int, int> dots_;         // whole dots per region (with masses_)
  std::map<int, std::vector<std::pair<double, double>>> centres_;  // whole dots' centres
  int screentone_ = -1;
  int lattice_state_ = -1;
  Lattice lattice_;
};
// Cost added to a strand join of regions a and b (joins.cpp) on a
// screentone drawing, where the colour says nothing (every window's spread
// is larger than the steps): -1.2 for pieces of one tone, +1 for two tones,
// -0.6 when both are paper-white (a third of the generator's strands are
// untoned; a toned piece and a white one are two strands: +0.6, as for a
// dark-share step over kMinOtherToneStep when the dots are not measured).
// 0 on other drawings.
double tone_join_cost(RegionTones& tones, int a, int b);
// Dark shares that say two tones without the dots: the darker piece toned
// (kMinTone) and the two more than kMinOtherToneStep apart.
bool dark_shares_apart(RegionTones& tones, int a, int b);
// Two strands by their dots (screentone drawings only; false elsewhere):
// both pieces' dots are measured and differ (`match` kOther), or one piece
// is paper-white and the other toned (dark shares over kMinTone and more
// than kMinOtherToneStep apart). The strand joins' tone cost only weighs
// this, so a pair whose outlines agree was joined all the same (session 23:
// on dev screentone seeds 2000, 3000, 4000 and 5000, 100 drawings each, 9
// edge links and one face link of such pairs were chosen, every one wrong);
// the mass and path joins refuse kOther too.
bool two_tones_by_dots(RegionTones& tones, int a, int b);
// The face mask grown by 3 px (what the path joins' face share reads),
// empty without a face.
cv::Mat near_face_mask(const cv::Mat& face);
// Options::face_piece_mass_step (session 33): on screentone, two pieces
// whose dots step more than it (RegionTones::mass_step, measured) while one
// of them runs along the face (`near_face`) for most of its outline: a
// strand lying on the face, no piece of the back hair that the back-hair
// passes (path, back paint, face and body joins) would join it to.
bool strand_on_face(const Context& ctx, RegionTones& tones, const cv::Mat& near_face, int a, int b);
// The colour at the 75th luma percentile of a region's own pixels in the
// 11 x 11 window round `at`: the paper between screentone dots (which cover
// under half of a tone).
Eigen::Vector3d light_colour_near(const Context& ctx, int region, const Vec2& at);
// Back hair with tails hanging from under it (`front` = regions above some
// region): the pieces lying above tails only, and the tails under them.
struct TailedHair {
  std::set<int> over_tails, tails;
};
TailedHair tailed_hair(const Context& ctx, const std::set<int>& front);
class RegionCels;
// On a cel drawing, a tail painted as the back hair (`RegionCels::judge`
// same as a back piece: a region above no region, or back hair over tails,
// that is no tail) is a piece of the back seen beside a strand lying on it
// (two-tone 106's 24 and 114's 25, each under one `behind` strand lying on
// back hair only), no tail: it leaves `tailed->tails` (session 14). The
// generator paints each tail in its own colour (over 3 RGB off the back).
void untail_back_paint(const Context& ctx, const std::set<int>& front, RegionCels& cels,
                       TailedHair* tailed);
// Candidates, surest (most rays both ways) first.
// `tones` and `fields` (join_paint.h) are the drawing's, shared by the
// join passes (each measures a region once).
class RegionFields;
std::vector<MassJoin> mass_join_candidates(const Context& ctx, RegionTones& tones,
                                           RegionFields& fields);

// Largest RGB step between two pieces of one paint (RegionCels::step on a
// cel drawing, RegionFields::step else): the generator varies each strand's
// colour a little, and two strands in nearly one paint step 1 RGB.
inline constexpr double kMaxOnePaintStep = 0.5;
// Whether a and b are painted alike: one tone by the dots on screentone
// (RegionTones::match), one flat paint on a cel drawing, else one linear
// colour field, within kMaxOnePaintStep. The back hair's path joins and the
// seam joins read it.
bool one_paint(RegionTones& tones, RegionFields& fields, int a, int b);
// Smallest RGB step between two pieces painted apart (RegionCels::step on a
// cel drawing, RegionFields::step else; RegionCels' own bar for "other"):
// the generator varies each strand's colour by up to 8 %. On dev mixed
// 2000-2099 and 3000-3099 the layering's weak `equal`s between pieces of
// one strand stepped at most 2 RGB where measured but two (3.1, 17),
// between two strands 3.0-77 RGB but two of one paint (session 23).
inline constexpr double kMinTwoPaintStep = 3.0;
// Whether a and b are measured to be painted apart: two tones by the dots on
// screentone (`two_tones_by_dots`: the dots measured and differing, or a
// paper-white piece beside a toned one, where the white piece was measured
// over room for RegionTones::kMinDots dot cells of the drawing's lattice,
// the bar for a region to show dots), else a finite step over
// kMinTwoPaintStep. Unlike !one_paint, a paint that cannot be measured (a
// piece too small for a field, no flat paint) says nothing. The paper-white
// case came with session 25 (joins50): on dev screentone 2000-2099 6 of the
// layering's weak equals between two strands whose dots were not measured
// joined a toned piece to a white one (none of the 155 true equals there
// pairs a white piece with a toned one), but a sliver of a toned strand
// holds no dot (dev screentone 3040's piece 13, 9 pixels measured; fresh
// mixed 7043's 18, 15), hence the room. Precision / recall with the
// layering's relations: screentone 2000-2099 0.888 / 0.633 -> 0.892 / 0.635
// (docs/completion-record.md, "Session 25: weak equals between a toned and a
// white piece").
bool two_paints(RegionTones& tones, RegionFields& fields, int a, int b);

// Back-hair pieces linked through the regions lying above both of them
// (mass_paths.cpp), after the mass and face joins: a piece facing another
// only through other back pieces, one way, or as a sliver too shallow for
// the rays above is still joined to it when a path runs from one to the
// other under their common occluders and the colour continues across it.
// Pieces lying above no region (or above tails only) and no tail. Smallest
// colour step first. Empty unless Options::path_joins.
// Pieces lying wholly along the `face` (CV_8U mask, may be empty) are strands
// lying on it, not back hair. Textured pieces (RegionTones) compare colours
// at the light percentile and must share their tone. Pairs already in one
// strand (`one_strand`, if given) are left out: joining them changes
// nothing, and their paths are the search's cost.
std::vector<MassJoin> path_join_candidates(const Context& ctx, const cv::Mat& face,
                                           RegionTones& tones, RegionFields& fields,
                                           const std::function<bool(int, int)>& one_strand = {});

// Mean colour of a region's drawn pixels (not outlines) within 5 px of the
// point 6 px from `at` along `inward`; `spread` (if given) gets their RGB
// standard deviation.
Eigen::Vector3d colour_near(const Context& ctx, int region, const Vec2& at, const Vec2& inward,
                            double* spread = nullptr);

}  // namespace hair25d::completion::detail
