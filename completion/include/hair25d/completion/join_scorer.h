// A learned scorer for case-1 strand-join candidates (paper §5.1): a small
// network reading the hand cost's terms and what they leave out (colour
// profiles across the pieces, what the join curve passes under, rivals).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hair25d::completion {

// Inputs of the scorer, all symmetric in the two pieces (join_features.cpp
// says what each is; `join_feature_name` names them).
// Session 35: inputs 44-53 describe an angle refusal's second chance
// (JoinScorerOptions::angle_refusal_threshold) and are 0 for every other
// candidate; the nets trained before them have zero weights there.
// Session 36: inputs 54-63 describe a cover refusal's second chance
// (JoinScorerOptions::cover_refusal_threshold), 0 for every other
// candidate; the nets trained before them have zero weights there (their
// files leave those inputs out).
// Session 37: inputs 64-74 describe a cut's second partner
// (JoinScorerOptions::second_partner_threshold: a candidate whose cut an
// earlier join took), 0 for every other candidate; likewise left out of
// the older nets' files.
// Session 39: inputs 75-76 say how each piece's own colour field predicts
// the other piece's paint at its cut (RegionFields::cross_miss), on shaded
// drawings painted by fields; −1 elsewhere. No committed net reads them.
inline constexpr int kJoinFeatures = 77;
inline constexpr int kJoinHidden = 12;
using JoinFeatures = std::array<float, kJoinFeatures>;

// "mean_angle", ...; throws hair25d::Error for an index out of range.
const char* join_feature_name(int index);

// One hidden layer of tanh units and a logistic output; inputs standardised
// by `mean` and `inv_std` first.
struct JoinScorerNet {
  std::array<float, kJoinFeatures> mean{}, inv_std{};
  std::array<std::array<float, kJoinHidden>, kJoinFeatures> w1{};
  std::array<float, kJoinHidden> b1{}, w2{};
  float b2 = 0.0f;
};

// Probability that the two pieces are one strand. Throws hair25d::Error for
// a feature that is not finite.
double join_probability(const JoinScorerNet& net, const JoinFeatures& features);

// The weights trained by bench/completion/train_join_scorer (generated file
// join_scorer_weights.cpp).
const JoinScorerNet& default_join_scorer();
// Session 18: the net for the candidates over the angle limit
// (JoinScorerOptions::max_angle_deg), trained on those alone (generated file
// join_scorer_wide_weights.cpp; retrained in session 29).
const JoinScorerNet& wide_join_scorer();
// Session 25: nets of several training seeds (generated file
// join_scorer_ensemble_weights.cpp), averaged where
// JoinScorerOptions::ensemble says; empty when none was trained.
std::span<const JoinScorerNet> ensemble_join_scorers();
// Session 26: the same for the drawings without screentone (flat, two-tone,
// gradient paint), trained on those drawings' candidates (generated file
// join_scorer_paint_ensemble_weights.cpp); empty when none was trained.
std::span<const JoinScorerNet> paint_ensemble_join_scorers();
// Session 29: the net retrained on 57 910 candidates of both relations and
// four shadings (session 28, joins61's N2; generated file
// join_scorer_retrained_weights.cpp), used in place of the default net on
// the drawings without screentone where JoinScorerOptions::retrained says.
const JoinScorerNet& retrained_join_scorer();
// Session 30: a net trained on the candidates of screentone drawings alone
// (both relations; generated file join_scorer_screentone_weights.cpp),
// judging the band's edges on screentone drawings where
// JoinScorerOptions::screentone_veto_below and screentone_rescue_threshold
// say.
const JoinScorerNet& screentone_join_scorer();
// Session 31: a net trained on the candidates of two-tone and gradient
// drawings alone (both relations; generated file
// join_scorer_shaded_weights.cpp), judging the band and its edges on the
// drawings told shaded from their paint where JoinScorerOptions::shaded
// says.
const JoinScorerNet& shaded_join_scorer();
// Session 35: a net trained on the second chances of angle refusals alone
// (JoinScorerOptions::angle_refusal_threshold; both relations, four
// shadings; generated file join_scorer_angle_weights.cpp).
const JoinScorerNet& angle_join_scorer();
// Session 36: the net for cover refusals' second chances only
// (JoinScorerOptions::cover_refusal_threshold; both relations, four
// shadings; generated file join_scorer_cover_weights.cpp).
const JoinScorerNet& cover_join_scorer();
// Session 37: the net for cover refusals' second chances on flat and
// screentone drawings (JoinScorerOptions::cover_flat_threshold,
// cover_screentone_threshold; both relations, those two shadings only;
// generated file join_scorer_cover_plain_weights.cpp).
const JoinScorerNet& cover_plain_join_scorer();
// Session 37: the net for a cut's second partners only
// (JoinScorerOptions::second_partner_threshold; both relations, four
// shadings, recorded inside the matching with the scorer on; generated
// file join_scorer_second_weights.cpp).
const JoinScorerNet& second_partner_join_scorer();
// The mean of the nets' probabilities (one net's alone when there is one):
// a wrong candidate that one training seed happens to trust is refused
// when the others do not. Throws hair25d::Error for no nets or a feature
// that is not finite.
double join_probability(std::span<const JoinScorerNet> nets, const JoinFeatures& features);

// When and how completion uses the scorer (completion::Options::join_scorer).
struct JoinScorerOptions {
  // Strand-join candidates whose hand cost lies in [band_low, band_high]
  // (where the cost does not separate right from wrong) are judged by the
  // scorer's probability p: with p >= threshold the cost becomes at most
  // max_join_cost + (threshold − p) × (band_high − band_low) (accepted, and
  // ranked by p); with p < refuse_below the candidate is refused; else the
  // hand cost stands. Session 14 (docs/completion-record.md): retrained on the
  // candidates of today's hand cost up to 4.0; with the band [1.4, 4.0] and
  // threshold 0.9 it raises recall on 10 of the 12 generated sets of seeds
  // 101-116, 201-216 and 401-416 and keeps the annotated six, but loses
  // 0.019 precision on flat 201-216: it stayed off. Session 17: retrained
  // with six inputs more (the dots' tone match and steps, the occluders
  // over the gap) on fresh seeds; it only rescues candidates over the
  // limit (band_low = max_join_cost 2.4) at p >= 0.8, which raises recall
  // on every 100-drawing dev set with precision within 0.003 with the
  // annotation's relations, but loses 0.004 on mixed with the layering's
  // (docs/completion-record.md "Session 17"). On the lead's held sets it raised
  // recall by 0.007-0.035 with the annotation's relations at the same
  // precision, and by 0.013-0.052 with the layering's at 0.001-0.005 less
  // precision: on since session 17.
  bool enabled = true;
  double band_low = 2.4, band_high = 4.0;
  double threshold = 0.8;
  // The threshold on screentone drawings (RegionTones::screentone), the
  // others' `threshold`. Session 21 (docs/completion-record.md): 0.65 raised
  // screentone recall by 0.009-0.021 on dev and fresh 100-drawing sets but
  // lost 0.006 / 0.003 precision on fresh 8000-8099 (annotation's /
  // layering's relations): left at `threshold`'s 0.8. Session 30: 0.9, with
  // the screentone net judging the band there (screentone_band; with the
  // default net, 0.8 as before).
  double screentone_threshold = 0.9;
  // Session 25: on which drawings the ensemble (ensemble_join_scorers) may
  // rescue a candidate of the band that the default net refuses: none,
  // screentone ones (RegionTones::screentone) or all; it does when the mean
  // of its nets' probabilities q >= ensemble_threshold (the cost becomes at
  // most max_join_cost + (ensemble_threshold − q) × (band_high − band_low)).
  // The committed ensemble: 4 seeds trained on screentone candidates of both
  // relations. With `kScreentone` it raised recall at equal or better
  // precision on every dev set with either relations (screentone 2000 with
  // the layering's 0.888 / 0.633 -> 0.890 / 0.646) but lost 2 wrong pairs on
  // fresh mixed 7000 with the annotation's (docs/completion-record.md
  // "Session 25"). On the lead's held sets it added right pairs only
  // (mixed 1000-1099 +4 / +4, screentone 1000-1049 +2 / +6 with the
  // annotation's / layering's relations, no wrong one): on for screentone.
  // Session 26: `kEach` also lets the paint ensemble
  // (paint_ensemble_join_scorers; 4 seeds trained on flat, two-tone and
  // gradient candidates of both relations) rescue on the drawings that are
  // no screentone, for pieces compared as flat paint (JoinTerms::flat_paint:
  // on gradients it gained nothing), at q >= paint_ensemble_threshold, or
  // cel_ensemble_threshold on a cel drawing (a base and a shadow band, told
  // by the shadow ratio its flat-painted pieces share: join_paint.h
  // shadow_ratio). Dev sets 2000 and 3000 (docs/completion-record.md
  // "Session 26"): +53 right pairs and -4 wrong ones over mixed, flat,
  // gradient and two-tone in both relations; at one threshold 0.95 for all,
  // two-tone 2084 lost precision (a right rescue joined to a piece already
  // joined wrongly), hence the cel drawings' higher bar. Fresh mixed 7000,
  // 8000 and flat 7000: right pairs only. Off by default: on the lead's
  // held flat set with the layering's relations it added 7 right and 8
  // wrong pairs (precision 0.954 -> 0.949): a wrong rescue (seed 1000) and a
  // right one that joined a piece already merged into another strand by a
  // false `equal` (seed 1022, 6 wrong pairs).
  enum class Ensemble { kNone, kScreentone, kAll, kEach };
  Ensemble ensemble = Ensemble::kScreentone;
  double ensemble_threshold = 0.95;
  double paint_ensemble_threshold = 0.9;
  double cel_ensemble_threshold = 0.965;
  double refuse_below = 0.0;
  // Session 29: on the drawings without screentone, judge the band by
  // retrained_join_scorer at retrained_threshold instead of the default net
  // at `threshold` (screentone drawings keep the default net: there the
  // retrained one's extra joins with the layering's relations were about
  // half wrong, docs/completion-record.md "Session 28: the changes together").
  bool retrained = false;
  double retrained_threshold = 0.9;
  // Session 29 (joins63): the retrained net judges the band's edges on the
  // drawings without screentone, whichever net judges the band (`retrained`
  // or the default one).
  // A candidate under the limit with hand cost in [veto_low, band_low) is
  // refused when the retrained net's p < veto_below (a refused wrong join
  // frees its pieces for right ones in the greedy matching); 0: none is.
  // A candidate with hand cost in (band_high, rescue_high] is joined when
  // p >= rescue_threshold (ranked as the band's rescues; its rivals still
  // counted up to band_high, as the nets were trained); rescue_high <=
  // band_high: none is. With `record`, candidates up to rescue_high are
  // recorded on every drawing. Held out (docs/completion-record.md
  // "Session 29: the scorer's band"), the retrained net's AUC is 0.93 on
  // candidates of hand cost 1.4-2.4 and 0.97-0.98 on 4.0-5.0. With
  // `retrained`, veto 1.4 / 0.2 and rescue 5.0 / 0.97 raised precision on
  // all ten generated dev sets and the eight fresh ones (9400, 9500) but
  // `retrained` itself lost precision on the lead's held flat set with the
  // layering's relations. With the default net judging the band (the
  // lead, "Session 29: the band's edges with the committed net") they raised
  // precision on every dev, fresh and held set; on by default.
  double veto_low = 1.4;
  double veto_below = 0.2;
  double rescue_high = 5.0;
  double rescue_threshold = 0.97;
  // Session 30 (joins67): the same two edges on screentone drawings, judged
  // by screentone_join_scorer: refused under the limit (hand cost in
  // [veto_low, band_low)) at p < screentone_veto_below (0: none is), joined
  // over the band (up to rescue_high) at p >= screentone_rescue_threshold
  // (1: none is). Held out (screentone 5900-5999, each relations), that net
  // refuses 26 and 24 wrong candidates of 1.4-2.4 at p < 0.2 for no right
  // one, and rescues 61 right ones of 4.0-5.0 for 1 wrong at p >= 0.9 (the
  // retrained net 31 / 1, 28 / 0). At 0.35 / 0.9 (docs/completion-record.md
  // "Session 30: screentone joins"): dev screentone 2000 and 3000 +75 right
  // pairs and -60 wrong ones over both relations, dev mixed +13 / -21, the
  // six unchanged; fresh screentone and mixed 9600 and 9700 +6 / -15.
  double screentone_veto_below = 0.35;
  double screentone_rescue_threshold = 0.9;
  // The veto's lower end on screentone drawings, `veto_low` elsewhere.
  // Session 32: the screentone net (trained on every candidate up to
  // band_high) refuses wrong joins under 1.4 too, which frees their edges
  // for right ones: at 0.6, dev screentone 2000 and 3000 over both
  // relations +22 right pairs and +1 wrong (docs/completion-record.md
  // "Session 32: the screentone veto lower").
  double screentone_veto_low = 0.6;
  // With screentone_band, the screentone net also judges the band there (at
  // screentone_threshold) in place of the default net. joins48 (session 25)
  // lost precision replacing the default net on screentone; with the edges
  // above and the bar at 0.9 (not 0.8) it adds, over the edges alone, 88
  // right pairs and 7 wrong ones on dev screentone and mixed 2000 and 3000
  // (both relations; the six unchanged) and 152 right and 14 wrong on fresh
  // screentone and mixed 9600 and 9700; edges and band together against
  // session 29's main: dev +176 / -74, fresh +158 / -1.
  bool screentone_band = true;
  // Session 31: on a shaded drawing (two-tone: a cel shadow band; gradient:
  // paint that is no cel paint; told from the drawing's paint, join_scoring.h
  // shaded_drawing), shaded_join_scorer judges the band's edges in place of
  // the retrained net: refused under the limit at p < shaded_veto_below (0:
  // none is), joined over the band at p >= shaded_rescue_threshold (1: none
  // is); with shaded_band it also judges the band at shaded_threshold in
  // place of the default net. Flat and screentone drawings keep their nets.
  bool shaded = false;
  bool shaded_band = true;
  double shaded_threshold = 0.9;
  double shaded_veto_below = 0.2;
  double shaded_rescue_threshold = 0.97;
  // Session 31: `retrained` on shaded drawings only (the retrained net
  // judges their band at retrained_threshold; flat drawings, where
  // `retrained` lost precision on the lead's held set, keep the default
  // net). With shaded_band on, the shaded net judges there instead. On
  // since the lead's held and fresh sets (held mixed, fresh two-tone,
  // gradient and mixed 10200: +38 right / -4 wrong pairs, held mixed with
  // the layering's relations -5 right; completion-record.md "Session 31:
  // the changes together").
  bool retrained_shaded = true;
  // Session 34 (lead): the bar of retrained_shaded's band, lower than
  // retrained_threshold. Most refusals of the band on two-tone and
  // gradient drawings over p 0.5 were right candidates (session 32,
  // joins74), and the lost links among them are often back hair, whose
  // pieces make many pairs. Dev two-tone and gradient 2000 and 3000, both
  // relations, right / wrong pairs added against 0.9: 0.85 +50 / -5, 0.8
  // +107 / -1, 0.75 +134 / +3, 0.7 +164 / +20; held mixed and fresh
  // two-tone, gradient and mixed: 0.8 +79 / +5, 0.75 +112 / +3
  // (completion-record.md "Session 34: the retrained net's bar on shaded
  // drawings").
  double retrained_shaded_threshold = 0.75;
  // Session 18: edge pairs whose tangents turn more than
  // Options::max_join_angle_deg (70°) from the join's chords but at most
  // max_angle_deg are strand candidates for the scorer alone: costed as any
  // other up to wide_band_high, judged by `wide_join_scorer` (trained on such
  // candidates only), joined at p >= wide_threshold and never by the hand
  // cost. With max_angle_deg <= max_join_angle_deg there are none. Mixed
  // and flat 100-drawing sets (docs/completion-record.md "Session 18"): recall
  // +0.002 to +0.008 with no wrong pair more; the annotated six unchanged.
  // Off by default (0): on the lead's held sets it gained 3 right pairs of
  // 1596 (flat) and 1 of 1722 (mixed) and cost `hair25d model` of a 1024²
  // 40-strand drawing about 0.1 s (0.86 -> 0.96 s, medians of 5), its
  // candidates each taking the coverage raster. 120 turns it on.
  // Session 29: the wide net retrained on 26 849 wide candidates of dev
  // seeds 4000-5399 (both relations, four shadings; held-out AUC 0.937 ->
  // 0.970 with the annotation's relations); a wide join is made after every
  // other candidate under the limit, and never on screentone drawings; the
  // coverage raster no longer looks the relations up per pixel, so 120
  // costs `hair25d model` of that drawing ~20 ms (docs/completion-record.md
  // "Session 29: wide candidates"). Still off: on dev it gains right pairs
  // but on mixed 2000 with the layering's relations a right wide join
  // merged strands the layering's equals had merged wrongly.
  double max_angle_deg = 0.0;
  double wide_band_high = 5.0;
  double wide_threshold = 0.95;
  // Session 31: an edge pair refused by max_join_angle_deg whose angles lie
  // within it once an unreliable edge (end tangents parting by over 45°, or
  // an end without visible outline) takes its side tangent (the middle line
  // of the two side outlines leaving the cut) for both ends is a candidate
  // joined only by the band's net at p >= side_threshold (hand cost up to
  // band_high), off screentone drawings. 1 turns it off. On since the
  // lead's held and fresh sets (held flat, mixed and the fresh lead sets:
  // +76 right / +2 wrong pairs over both relations; completion-record.md
  // "Session 31: the changes together").
  double side_threshold = 0.9;
  // Session 32 (joins74): a second opinion on the band's refusals where
  // the default net judges the band (flat drawings: not screentone, not
  // shaded, `retrained` off). A band candidate it refuses with p in
  // [second_low, threshold) is joined when the retrained net gives
  // q >= second_threshold; such a join is made after every candidate under
  // the limit (as a wide one), so it only takes edges no other join wants.
  // On dev flat 2000 the default net's band refusals at 0.5-0.8 were 120 /
  // 14 right / wrong candidates, which the retrained net separates (AUC
  // 0.87; the default net 0.54): at q >= 0.9 it keeps 44 / 0. At 0.5 /
  // 0.85: dev flat and mixed 2000 and 3000 +52 right pairs, 0 wrong; fresh
  // flat and mixed 10400-10599 +73 / +2 (both relations). The shaded net
  // as the second opinion on shaded drawings lost precision on dev
  // two-tone 3000 (docs/completion-record.md "Session 32: a second opinion
  // on the band's refusals"). second_threshold 1 turns it off.
  double second_low = 0.5;
  double second_threshold = 0.85;
  // Session 35 (joins81): a cut pair refused by max_join_angle_deg that no
  // side tangent brings within it (screentone drawings too) is tried with
  // other tangents for each edge: one end's for both, its own reversed, its
  // side tangent, the direction its opposite ends dropped (Edge::
  // turned_tangent); the choice with the smallest worst angle, if within
  // the limit and its hand cost within band_high, is judged by
  // `angle_join_scorer` alone (trained on such candidates, with inputs
  // saying which tangents were used and how much outline backs them) and
  // joined at p >= angle_refusal_threshold, after every other candidate
  // under the limit. 1 turns it off. On at 0.9 since session 35 (lead's
  // held and fresh sets, both relations: +133 right / 0 wrong pairs).
  double angle_refusal_threshold = 0.9;
  // Whether it also tries the readings that turn an edge's outline round
  // (its own tangents reversed, the direction its opposite ends dropped);
  // candidates recorded with the scorer off always do (the net's training
  // data).
  bool angle_refusal_turned = false;
  // Session 36: a strand-join candidate refused only because its patch
  // lies under min_join_coverage (not over another back paint, no corridor,
  // within the angle limit with its own tangents, hand cost before the
  // cover term up to band_high) is asked of `cover_join_scorer` alone
  // (trained on such candidates, with inputs saying what lies where the
  // patch is uncovered) and joined at p >= cover_refusal_threshold, after
  // every other candidate under the limit, as the angle refusals' second
  // chances are. 1 turns it off. On at 0.9 since session 36 (held and
  // fresh sets +127 right / +2 wrong pairs, the six real cases unchanged;
  // completion-record.md, "Session 36: cover refusals' second chances on
  // by default").
  double cover_refusal_threshold = 0.9;
  // Whether it also acts off two-tone and gradient drawings (flat and
  // screentone ones; `shaded_drawing`). Off: there the dev sets lost
  // precision (flat, mixed and screentone 2000 with the annotation's
  // relations: +19 right / +40 wrong pairs at 0.9, a wrong join each of
  // a few drawings); candidates recorded with the scorer off always are.
  bool cover_refusal_all_shadings = false;
  // Session 37: on flat drawings (neither screentone nor `shaded_drawing`)
  // and on screentone ones, the cover refusals' second chances are asked
  // of `cover_plain_join_scorer` instead (trained on those two shadings'
  // second chances alone) and joined at p >= these bars, each 1 = off.
  // cover_refusal_all_shadings, when set, keeps session 36's net there.
  // Flat on at 0.97 (dev flat 2000 and 3000, both relations: +43 right /
  // 0 wrong pairs at 0.95; on the lead's held and fresh sets 0.95 added
  // +123 / +15, 0.97 +101 / +3); screentone off: there the net trusts
  // wrong joins of long patches across the drawing (dev +56 / +20 at
  // 0.95, +29 / +8 at 0.99; completion-record.md, "Session 37: cover
  // refusals' second chances on flat and screentone drawings" and
  // "Session 37: the flat cover second chances' bar").
  double cover_flat_threshold = 0.97;
  double cover_screentone_threshold = 1.0;
  // Session 37: a candidate the greedy matching refuses because an earlier
  // join took the atoms of one of its edges (each of its cuts may join
  // once, a second time at Options::second_partner_p) is asked of
  // `second_partner_join_scorer` (trained on such candidates, with inputs
  // saying how sure the scorer was of it and of the first join, and how
  // the two partners lie along the cut) and joined there, at its place in
  // the matching, at p >= second_partner_threshold. 1 turns it off. On at
  // 0.9 since session 37 (joins88: dev two-tone, gradient and mixed 2000
  // and 3000, both relations, +90 right / 0 wrong pairs; fresh 31100-31299
  // +66 / +5; the six real cases unchanged).
  double second_partner_threshold = 0.9;
  // Whether it also acts off two-tone and gradient drawings
  // (`shaded_drawing`): flat and screentone ones.
  bool second_partner_all_shadings = false;
  // Whether the second partners the net accepts wait until every other
  // candidate is matched, then join the surest first, each asked again
  // (as the angle and cover refusals' second chances rank last: they take
  // only cuts no other join wants); false: each joins at its own place in
  // the matching.
  bool second_partner_last = true;
  // Session 39: on shaded drawings painted by colour fields (gradient), a
  // candidate its net refuses — a band candidate, one over the band, an
  // angle refusal's second chance — joins when each piece's own field
  // predicts the other piece's paint at its cut within field_cross_max
  // RGB (inputs 75-76, RegionFields::cross_miss) and its net gives it at
  // least field_cross_low; after every other candidate under the limit,
  // the surest first. 0 turns it off. Session 39 (joins94) at 3 / 1.5 /
  // 0.3: dev gradient and mixed 2000, 3000, both relations, +65 right / +1
  // wrong pairs; fresh 31700 +23 / 0; flat, two-tone, screentone and the
  // six real cases unchanged (completion-record.md, "Session 39: the
  // pieces' colour fields across the gap"). On the lead's held and fresh
  // sets 0.3 let in a wrong pair in eight (p 0.32-0.50), so the bar is 0.5:
  // +80 right / +4 wrong there, dev and fresh 31700 +49 / +1 ("Session 39:
  // the fields' rule on the lead's sets").
  double field_cross_max = 3.0;
  double field_cross_low = 0.5;
  // Or the larger piece's field (input 76) alone within this RGB (0: not).
  double field_cross_larger_max = 1.5;
  // Record every strand-join candidate with hand cost ≤ band_high in
  // Result::join_candidates (training data; changes no join).
  bool record = false;
  // Session 28: with `record`, also a crop of the drawing around each
  // candidate, crop_size² pixels a channel (JoinCandidate::crop); 0: none.
  int crop_size = 0;
  bool is_valid(std::string* error) const;
};

// A strand-join candidate as completion saw it.
struct JoinCandidate {
  int region_a = 0, region_b = 0;
  double hand_cost = 0.0;     // the hand-made cost (joins.cpp)
  double cost = 0.0;          // the cost ranked (the scorer's when it decided)
  double probability = -1.0;  // the scorer's, or −1 when it was not asked
  bool chosen = false;        // made by the greedy matching
  JoinFeatures features{};
  // With JoinScorerOptions::crop_size > 0: kJoinCropChannels planes of
  // crop_size² bytes, row-major, aligned to the join (join_crop.h).
  std::vector<std::uint8_t> crop;
};

// Channels of JoinCandidate::crop: the drawing's red, green and blue (over
// white paper), then masks of piece a, piece b, the regions above either
// piece, other hair regions, and the hidden patch (255 inside).
inline constexpr int kJoinCropChannels = 8;

struct JoinTrainingOptions {
  int epochs = 60;
  int batch = 64;
  double rate = 3e-3;   // Adam's step
  double decay = 1e-4;  // L2 on the weights (not the biases)
  std::uint64_t seed = 1;
  bool is_valid(std::string* error) const;
};

struct JoinTrainingResult {
  JoinScorerNet net;
  int epochs = 0;           // passes made (all of them: no early stop)
  double final_loss = 0.0;  // weighted mean logistic loss of the last pass
};

// Adam on the logistic loss, classes weighted to equal total weight;
// deterministic for one seed (one thread, a fixed shuffle). `labels` 1 =
// one strand, 0 = two. Throws hair25d::Error for sizes that differ, fewer
// than 2 rows of each class, labels other than 0 / 1, non-finite features
// or invalid options.
JoinTrainingResult train_join_scorer(const std::vector<JoinFeatures>& rows,
                                     const std::vector<int>& labels,
                                     const JoinTrainingOptions& options = {});

// The C++ source of join_scorer_weights.cpp defining default_join_scorer()
// as `net` (floats printed to round-trip exactly); `comment` heads the file.
std::string join_scorer_source(const JoinScorerNet& net, const std::string& comment,
                               const std::string& function = "default_join_scorer");
// The same for several nets: `function` returns them as a span.
std::string join_scorer_ensemble_source(std::span<const JoinScorerNet> nets,
                                        const std::string& comment,
                                        const std::string& function = "ensemble_join_scorers");

}  // namespace hair25d::completion
