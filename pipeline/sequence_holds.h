#pragma once

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// The sequence policy: what a frame takes from the previous frames' geometry (SequencePrior).
// Each adds a note to result->fallback when it changes the geometry.

// A junction line at least this confident (JunctionLine::confidence: boundary score times support
// length) is strong evidence of its own: a frame whose confidence is not in doubt keeps it against
// the sequence. Such a line mistaken for the floor's edge is a real boundary, the foot of a box or
// a pillar whose face stands nearer than the wall: moving the wall behind it puts the layout right
// but draws the near depth far worse than the frame's own (the face is where that depth is).
inline constexpr double kStrongJunction = 0.75;

// Whether a frame's own evidence is in doubt, so that the sequence may overrule it (HoldWidth,
// ScaleWallsToCeiling): its own confidence (on its own geometry, before any hold) below
// min_confidence, its two ceiling sides measurably disagreeing (ceiling_disagreement >= 0 and
// above max_disagreement; -1 when they cannot be compared), or its junctions the tracker's (found
// near the previous frame's, not by the frame's own search).
bool FrameInDoubt(double own_confidence, double min_confidence, double ceiling_disagreement,
                  double max_disagreement, bool junctions_tracked);

// Whether a frame confirms the junction track: a whole search that agrees with the pair tracked
// into it may have found the same wrong lines twice (a box's foot kept from frame to frame), and
// a tracked line may drift onto another one, so the track is trusted on only while each frame
// ends ok with its two ceiling sides, each searched alone, agreeing with its walls
// (ceiling_trusted). A searched frame that does not confirm leaves the next frame to a whole
// search (JunctionTrack::Unconfirmed); a tracked one is itself searched whole again, and the track
// goes on from that search (DepthRecoverer::Recover, FramePipeline). Without a ceiling search (a
// given ceiling height, or none estimated) there is nothing to confirm: true.
bool TrackConfirmedBy(const RecoverDepthOptions& options, const RecoverDepthResult& result);

// Whether a tracked frame (its junctions the tracker's, confirmed by its ceiling) takes instead
// the answer of its own whole search, `own`: when that answer is ok and its two ceiling sides,
// each searched alone, agree with its walls (ceiling_trusted), the frame's own evidence is strong
// and the sequence does not change it (a tracked line, even the same line, fits its points a few
// millimetres differently from the searched one, and may have drifted onto a line the frame's own
// search would not take). The tracked lines stand only for a frame whose own search fails or is
// not confirmed. Without a ceiling search nothing confirms the frame's own search: false.
bool OwnSearchKept(const RecoverDepthOptions& options, const RecoverDepthResult& own);

// When a frame whose own confidence was below min_confidence ends with its width held and a
// confidence at or above it, notes that the hold rescued it. True when it did.
bool NoteRescue(double own_confidence, double min_confidence, RecoverDepthResult* result);

// In a sequence, a width much narrower than the previous frame's (max_change) means that one
// junction is wrong (a box edge or a grout line taken for it). Only a narrower width: the lines
// mistaken for a junction lie inside the floor, while a wider width is as often the correction of
// an earlier mistake.
bool MuchNarrower(const CorridorGeometry& previous, double max_change, const CorridorGeometry& g);

// Holds such a width: one wall stays and the other is put at the recent width from it
// (result->width_held). The wall that stays is the one whose ceiling (result->ceiling's side
// heights, each side searched alone) agrees with the trusted ceiling `previous` carries, when one
// side's height above the camera is off from it by more than max_change (|log ratio|: a wall put
// too near scales its side's height by the same factor) and the other by less than half as much
// and by no more than max_change (a side off by more has a wrong wall too: both walls were put
// too near, and keeping either would put the other far beyond the truth).
// Otherwise (no trusted ceiling, a side without a height, no clear answer), the wall that moved
// less since the recent frames. Only a frame whose own evidence is doubted (`frame_doubted`: its
// confidence below min_confidence, its two ceiling sides measurably disagreeing, or tracked
// junctions) is held: which wall moved less is a guess, and even the ceiling's answer does not
// tell a line inside the floor from the foot of a box's face standing before the wall, whose near
// depth the frame's own layout draws right. A frame that is not doubted keeps its width, with a
// note (result->width_kept: the sequence does not learn that width, SequencePrior).
void HoldWidth(const CorridorGeometry& previous, double max_change, bool frame_doubted,
               CorridorGeometry* g, RecoverDepthResult* result);

// The ceiling is as constant as the width: a frame in doubt (`frame_doubted`: its own confidence
// below min_confidence, or tracked junctions) whose ceiling is not trusted (not found, its two
// sides too weak to compare, or disagreeing because a wall distance is wrong and so its side's
// height) takes the previous trusted height (result->ceiling_held). A frame not in doubt keeps its
// own ceiling, or none, with a note (result->ceiling_kept): the trusted height came with the
// recent frames' walls, which may be the ones wrong. Sets result->ceiling_trusted in every case.
// `previous` (may be null) carries a ceiling only when one was trusted (SequencePrior).
void HoldCeiling(const CorridorGeometry* previous, double max_disagreement, double min_support,
                 bool frame_doubted, CorridorGeometry* g, RecoverDepthResult* result);

// Whether HoldCeiling would replace the frame's ceiling with `previous`'s, not knowing yet whether
// the frame is in doubt: the frame's ceiling is not trusted and a trusted one is carried. Sets
// result->ceiling_trusted.
bool CeilingHoldConsidered(const CorridorGeometry* previous, double max_disagreement,
                           double min_support, const CorridorGeometry& g,
                           RecoverDepthResult* result);

// A ceiling whose two sides agree (trusted) but whose height above the camera is far from the last
// trusted one's, with the width off by the same factor: both walls were put wrong by that factor
// (lines inside the floor on both sides, as boxes' edges are, put both walls too near, and their
// two ceiling sides, each scaled alike, agree with each other). The corridor's ceiling does not
// change along it, and a corridor that narrows keeps its ceiling: both walls are scaled out to the
// trusted ceiling (result->walls_scaled). Only out: lines inside the floor put walls too near,
// never too far, so a frame wider and higher than the trusted ceiling is this frame right and the
// trusted ceiling (from frames whose junctions were wrong alike) wrong. Only a frame in doubt
// (`frame_doubted`, as for HoldWidth) is scaled: one whose own evidence is strong is left alone,
// with a note (the recent frames may be the ones wrong alike).
// The factor ScaleWallsToCeiling would scale both walls by (above 1 + max_change); 0 when it
// would not.
double WallScaleFactor(const CorridorGeometry& previous, double max_change,
                       const CorridorGeometry& g, const RecoverDepthResult& result);
void ScaleWallsToCeiling(const CorridorGeometry& previous, double max_change, bool frame_doubted,
                         CorridorGeometry* g, RecoverDepthResult* result);

}  // namespace corridor
