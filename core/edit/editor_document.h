#pragma once
// EditorDocument: what the interactive editor edits, with no GL or ImGui (docs/architecture.md §1). The UI
// calls these methods and reads the parts it exposes (paths(), models(), history()) instead of
// one-line forwards; tests do the same directly. It coordinates four parts, each testable alone:
//
//   store     ClipEdits: the clip (unwrapped), accepted poses per frame, foot contacts
//   drag      DragSession: the drag state machine  beginDrag(e) -> dragTo(target)* / refine()* -> endDrag(),
//             and the latent drag
//   paths     PathSession: the effector path being edited (keys, offsets, mode)
//   models    ModelHost: the current immutable model version, the adaptive worker and its history
//
// and owns what ties them together: the current frame, the pins, the regeneration job, the
// undo history (undo also restores the model version a step changed) and the revision counter.
//
// Its definitions are in three files, by section of this header: editor_document.cpp (clip,
// model, undo / redo), editor_document_drag.cpp (pins, held effectors, drag) and
// editor_document_spans.cpp (path editing, keys and in-betweening).
//
// Units: cm, world Y up (docs/maths.md, conventions). One drag, one latent drag, one regeneration or one
// cleared edit = one undo step.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "edit/adaptive_worker.h"
#include "edit/clip_edits.h"
#include "edit/compare_mode.h"
#include "edit/deferred_teaching.h"
#include "edit/drag_session.h"
#include "edit/edit_history.h"
#include "edit/edit_record.h"
#include "edit/model_host.h"
#include "edit/path_edit.h"
#include "edit/path_session.h"
#include "edit/regenerate_job.h"
#include "edit/steady_verdict.h"
#include "eval/admission.h"
#include "ik/constrained_ik.h"
#include "motion/foot_contacts.h"
#include "motion/inbetween.h"
#include "skeleton/clip.h"
#include "util/background_worker.h"

namespace mgp {

// What one drag changed (returned by endDrag; the undo history keeps it as one step).
struct DragRecord {
    int frame = 0;
    Effector effector = Effector::kRFoot;
    std::optional<EditRecord> before;  // the frame's edit before the drag (none = captured pose)
    EditRecord after;
    int modelVersionBefore = 0;
};

class EditorDocument {
public:
    EditorDocument();
    ~EditorDocument();
    EditorDocument(const EditorDocument&) = delete;
    EditorDocument& operator=(const EditorDocument&) = delete;

    // ---- clip ------------------------------------------------------------------------------
    // Replaces the clip (edits, pins and drag are cleared). A model trained on another clip is
    // dropped unless `keepModel` (used by setModel, whose clip this is).
    void setClip(Clip clip, bool synthetic = false);
    const Clip& clip() const { return store_.clip(); }
    bool hasClip() const { return !store_.empty(); }
    bool synthetic() const { return store_.synthetic(); }
    // Any open clip trains (ASF/AMC, BVH, the synthetic clip).
    bool trainable() const { return hasClip(); }
    int frame() const { return frame_; }
    int frameCount() const { return store_.frameCount(); }
    void setFrame(int frame);  // clamped; ends a drag in progress (accepting it)
    const Pose& currentPose() const;
    const Pose& capturedPose() const { return clip().frames[frame_]; }
    // Frame `frame`'s pose in the edited motion (its edit, else the captured pose); a drag in
    // progress shows only on the current frame (currentPose).
    const Pose& poseAt(int frame) const { return store_.pose(frame); }
    bool isEdited(int frame) const { return store_.isEdited(frame); }
    const std::map<int, EditRecord>& edits() const { return store_.edits(); }
    void clearEdit(int frame);  // one undo step
    // Pastes `pose` (copied from any frame of this clip) onto the current frame as one undo step;
    // the current frame's root position is kept so the character does not jump. "" or why not.
    std::string pastePose(const Pose& pose);
    // What a whole-pose change does with what its frame keeps in place (keptInPlace()).
    enum class PoseHolds {
        kNone,     // the pose as given; the spread holds what the layered motion has
        kResolve,  // paste, mirror: re-solved under the prior so that the holds stay, and the spread
                   // holds them where they were before the change
        kSolved,   // rotate joint: the pose already keeps its holds (it was solved or settled
                   // with them); the spread holds them where they were, except `followLayer`
    };
    // Replaces the current frame's pose (root included) as one undo step named `stepLabel`: the
    // operations that compute a whole pose (paste, mirror, rotate joint) go through here, and the
    // change spreads over the falloff. With kResolve and a model, the pose is first re-solved under
    // the prior so that the frame's pins, placed effectors and planted feet stay where they were,
    // settled onto them by the hips and legs if the prior cannot reach them from the frame's root
    // (settleOnHolds); if they cannot all be met the pose is kept as given. `followLayer`
    // (kSolved): held effectors the change moved on purpose, held on the neighbours where the
    // change's layer carries them. "" or why not.
    std::string setCurrentPose(const Pose& pose, const std::string& stepLabel, PoseHolds holds = PoseHolds::kNone,
                               const std::vector<Effector>& followLayer = {});
    // What such a re-solve keeps in place: holdConstraints() and the planted feet, each once.
    std::vector<IkConstraint> keptInPlace() const;
    // Replaces every edit at once (loading a session); clears the undo history.
    void restoreEdits(std::map<int, EditRecord> edits);
    // The undo history of a saved session (after restoreEdits). Its steps restore frames only:
    // the model versions they once changed are not in the session (docs/architecture.md §9).
    void restoreHistory(std::vector<EditStep> undo, std::vector<EditStep> redo);
    const EditHistory& history() const { return history_; }
    Eigen::Vector3d effectorPosition(Effector e) const;  // FK of the current pose (cm)
    bool hasEffector(Effector e) const { return hasClip() && clip().skeleton.hasEffector(e); }

    // ---- model -----------------------------------------------------------------------------
    // Installs a model (its clip becomes the document's clip if `adoptClip`); restarts the
    // adaptive worker on it.
    void setModel(gp::ModelVersionPtr version, bool adoptClip);
    void clearModel();
    // A model published while its training run goes on (TrainingJob::takeRefinement), installed
    // as setModel does; until finishRefinement, accepted poses wait instead of being taught to
    // a model the next refinement replaces (docs/maths.md §23).
    void installRefinement(gp::ModelVersionPtr version, bool adoptClip);
    // The run's final model: installed, and each waiting pose still on its frame is taught to it
    // (its latent point found on this model, admitted as a drag's pose is). Returns how many were
    // posted.
    int finishRefinement(gp::ModelVersionPtr version, bool adoptClip);
    bool refining() const { return refining_; }
    int waitingPoses() const { return static_cast<int>(deferred_.size()); }
    gp::ModelVersionPtr model() const { return models_.current(); }  // the latest version (null if none)
    bool hasModel() const { return models_.hasModel(); }
    void setAdaptiveEnabled(bool on);
    // The model host's state, read-only (adaptive on, pending updates, status, update count and
    // history): its changes go through the document (setModel, setAdaptiveEnabled, undo).
    const ModelHost& models() const { return models_; }
    // Holds posted adaptive updates back until released (tests: "update running" without a race).
    void holdAdaptiveUpdates(bool on) { models_.holdUpdates(on); }
    void restoreAdaptiveHistory(std::vector<AdaptiveHistoryEntry> entries) {
        models_.restoreHistory(std::move(entries));
    }
    // The comparison model for CompareMode::kSecondModel (e.g. SGPLVM beside FASGPLVM).
    void setCompareModel(gp::ModelVersionPtr version) {
        compareModel_ = std::move(version);
        ++revision_;
    }
    gp::ModelVersionPtr compareModel() const { return compareModel_; }
    void setCompareMode(CompareMode mode);
    CompareMode compareMode() const { return compare_; }
    // The compare ghost for the current targets (none when not dragging or mode is none).
    const std::optional<Pose>& comparePose() const { return drag_.comparePose(); }

    // Latent point shown for the current frame: the drag's x, else the frame's accepted x, else
    // latentStartForFrame (cached per frame and model version). Empty without a model.
    Eigen::VectorXd currentLatent();
    // Latent points visited by the current drag (or the last one), in order.
    const std::vector<Eigen::VectorXd>& latentPath() const { return drag_.latentPath(); }

    // ---- pins ------------------------------------------------------------------------------
    // A pin holds the effector at its position in the current frame's pose (re-read when the
    // frame changes, so a planted foot stays planted wherever it is on that frame).
    void togglePin(Effector e);
    void setPinned(Effector e, bool on);
    bool pinned(Effector e) const { return pins_[static_cast<int>(e)]; }
    std::vector<Effector> pinnedEffectors() const;
    // A foot in ground contact on the current frame (core/motion/foot_contacts.h) is held like a
    // pin during a drag of another effector, unless released here (released feet stay released
    // until set back, on every frame).
    bool inContact(Effector foot) const;
    void setContactReleased(Effector foot, bool released);
    // What an edit of the current frame holds in place: every pin at its pin position, and every
    // foot in contact that is not released, where it is (a drag leaves out its own effector).
    std::vector<IkConstraint> pinConstraints() const;
    std::vector<IkConstraint> contactHolds() const;
    bool contactReleased(Effector foot) const { return contactReleased_[static_cast<int>(foot)]; }

    // ---- held effectors (edit/held_effectors.h) ----------------------------------------------
    // What the animator placed on the current frame and has not released, in effector order: a
    // drag here holds these where they are, and a later falloff holds them on its frames.
    std::vector<Effector> heldEffectors() const;
    bool held(Effector e) const;
    bool anythingHeld() const;  // on any frame
    // Releases `e` on the current frame and the neighbouring frames the same gesture held it on
    // (one undo step); "" or why not.
    std::string releaseHeld(Effector e);
    // Releases every held effector on every frame (one undo step); "" or why not.
    std::string releaseAllHeld();
    // What a drag of the current frame holds exactly: every pin at its pin position and every held
    // effector where it is (a drag leaves out its own effector).
    std::vector<IkConstraint> holdConstraints() const;

    // ---- drag ------------------------------------------------------------------------------
    // Returns "" when the drag started, else why not (no clip, effector absent).
    std::string beginDrag(Effector e);
    // Solves for a new target, warm-started from the previous solve (iteration cap per event).
    void dragTo(const Eigen::Vector3d& targetCm, int maxIterations = 50);
    // More iterations on the same target while the user holds still; false if nothing to do
    // (converged, no drag, or the refinement budget is spent).
    bool refine(int maxIterations = 50);
    // Accepts the pose (refining a little more first if it has not converged) and posts it to
    // the adaptive worker if admitPose admits it (every constraint reached, nothing through
    // the floor, the body like the capture); a refused pose stays an edit, and the update table
    // and status say why. Returns what changed.
    std::optional<DragRecord> endDrag();
    // Drag falloff radius r in frames (motion/drag_falloff.h): with r > 0 and a model, a drag on
    // frame t is re-solved over t−r..t+r in the background on release and merged into the drag's
    // own undo step. 0 edits the dragged frame only. Opening a clip sets the default, a quarter second
    // (defaultFalloffRadius: 30 frames at 120 fps).
    void setDragFalloff(int frames) { falloffRadius_ = std::max(0, frames); }
    int dragFalloff() const { return falloffRadius_; }
    // How strongly the body away from the dragged or edited limb keeps its pose (ik/locality.h), as
    // a multiple of the solvers' defaults: 1 the default, 0 off (the prior alone decides). Drags,
    // their falloff and path regeneration all use it.
    void setBodyStiffness(double scale);
    double bodyStiffness() const { return bodyStiffness_; }
    void cancelDrag();  // restores the pose before the drag
    bool dragging() const { return drag_.active(); }
    Effector dragEffector() const { return drag_.effector(); }
    Eigen::Vector3d dragTarget() const { return drag_.target(); }
    const SolveReadout& readout() const { return drag_.readout(); }
    // σ²(x), L_IK and the admission verdict of the current frame's solved pose against the latest
    // model version's training range: the live drag solve, else the frame's accepted edit (its pose
    // re-evaluated at its x, or, once an update taught the model the pose, at the latent point that
    // update gave the new training row, so the verdict judges the model that holds it). None without a
    // model, on a captured frame, or for an edit without a latent point (plain IK).
    std::optional<AdmissionVerdict> currentPoseVerdict() const;
    // What the range tint and its legend show for the current frame: its own verdict, steadied over
    // its edited neighbours (edit/steady_verdict.h), except during a drag, on the last drag's pose
    // and for a refusal that is not about the capture's range (out of reach, through the floor, off
    // balance). The frame and its neighbours are judged on one model version; each neighbour once
    // per pose, model version and contact switches (a cache).
    std::optional<ShownVerdict> shownPoseVerdict() const;
    // Whether `edited` on clip frame `frame` keeps the balance its captured pose had on the planted feet.
    Balance balanceOf(int frame, const Pose& edited) const;

    // Latent drag: pose the current frame from the model mean f(x) (root translation kept).
    bool beginLatentDrag();
    void latentDragTo(const Eigen::VectorXd& x);
    void endLatentDrag();
    bool latentDragging() const { return drag_.latentActive(); }

    // ---- path editing (docs/maths.md §12) --------------------------------------------------
    // Starts editing `e`'s path with the default keys around the current frame; "" or why not.
    std::string beginPathEdit(Effector e);
    // The path being edited (edit/path_session.h): its keys, offsets and mode, set and read
    // there (each change counts as a change to save); a regeneration reads it when it starts.
    PathSession& paths() { return paths_; }
    const PathSession& paths() const { return paths_; }
    // Solves the span between the first and last key on a background thread; "" or why not.
    std::string startRegenerate(int maxIterations = 500);
    bool regenerating() const { return regenerate_.running() || fill_.busy(); }
    int regenerateDone() const { return regenerate_.framesDone(); }
    int regenerateTotal() const { return regenerate_.framesTotal(); }
    void cancelRegenerate() {
        regenerate_.cancel();
        fill_.cancel();
    }
    // Call once per UI frame: a finished regeneration becomes one undo step (and the moved keys'
    // poses are posted to the adaptive worker). Returns a summary when it applied one, or why the
    // last pose change could not be spread (it stays a one-frame edit: e.g. on the clip's first
    // or last frame), else ""; `error` is set when the job failed or was cancelled.
    std::string pollRegenerate(std::string* error = nullptr);
    // Foot contacts of the clip (motion/foot_contacts.h), held by Regenerate and drag falloff;
    // the user can switch one off.
    const ContactSet& contacts() const { return store_.contacts(); }
    void setContactEnabled(std::size_t index, bool on);
    // The last finished path regeneration's span report (motion/motion_quality.h), if any (a drag's
    // falloff reports in the status line, not here).
    const std::optional<SpanQuality>& lastRegenerateQuality() const { return lastRegenerateQuality_; }
    // Its inner keys (frame, distance from the path, met or not); empty before the first one.
    const std::vector<MotionEditJob::KeyResult>& lastRegenerateKeys() const { return lastRegenerateKeys_; }

    // ---- keys and in-betweening ------------------------------------------------------------
    // Frames the animator marked as keys (0-based). Fill between keys regenerates the frames
    // strictly between the two keys around the playhead from the keys' poses, the frames around
    // them and the model's training clips (motion/inbetween.h), as one undo step.
    const std::set<int>& keys() const { return keys_; }
    void toggleKey(int frame);
    // Replaces the keys (loading a session); "" or why not (a frame outside the clip).
    std::string restoreKeys(std::set<int> keys);
    // The gap a fill at `frame` fills: the last key at or before it and the first key after that,
    // with at least one frame between; none otherwise.
    std::optional<InbetweenGap> keyGapAt(int frame) const;
    // Every gap between consecutive keys that both lie in first..last.
    std::vector<InbetweenGap> keyGapsIn(int first, int last) const;
    // Fills on a background thread, as one undo step: the gaps between the keys inside `range`
    // (frames first..last, 0-based) or, without one, keyGapAt(frame()). "" or why not. While it
    // runs, regenerating() is true (undo, poses and paths wait for it, drags are refused) and
    // cancelRegenerate() cancels it too.
    std::string startFill(InbetweenMethod method = InbetweenMethod::kPrior,
                          std::optional<std::pair<int, int>> range = std::nullopt);
    bool filling() const { return fill_.busy(); }
    // Call once per UI frame: a finished fill becomes one undo step. Returns its summary, else "";
    // `error` is set when it failed or was cancelled.
    std::string pollFill(std::string* error = nullptr);

    // ---- undo / redo -----------------------------------------------------------------------
    bool canUndo() const { return history_.canUndo(); }
    bool canRedo() const { return history_.canRedo(); }
    std::string undoLabel() const;  // "" when there is nothing to undo
    std::string redoLabel() const;
    // Restore the frames and the model version a step changed. Undo first waits for adaptive
    // updates still running (they are part of the step). "" or why not.
    std::string undo();
    std::string redo();
    // The current frame's pose before the last undoable step that touched it (before/after ghost).
    std::optional<Pose> beforeGhost() const;
    // Grows with every change a session saves (edits, model versions, paths): compare two values
    // to know whether there are unsaved changes.
    long revision() const { return revision_.load(); }

    // Blocks until background updates and a running regeneration finish (tests and scripts).
    void waitIdle();

private:
    void updatePinPositions();
    long pushStep(EditStep step);  // the step's id
    std::string releaseBlocked();  // "" when a release can run now (a finished spread applied first)
    std::string applyRelease(const FrameEdits& change, std::string label);
    // Spreads a changed frame over the falloff span; `wholePose` (paste, mirror, rotate) layers the
    // whole change over the span first (motion/pose_layer.h); `holdInPlace`: what is held on the
    // neighbours is held where it was before the layer (EditBase::holdFrames), except
    // `followLayer` (EditBase::followLayer).
    void startDragFalloff(const DragRecord& rec, long stepId, const std::string& stepLabel, bool wholePose = false,
                          bool holdInPlace = false, const std::vector<Effector>& followLayer = {});
    void finishRunningFalloff();
    void dropRunningFalloff();
    void stopRegeneration();
    void applyFrames(const FrameEdits& frames);
    void installVersion(const gp::ModelVersionPtr& version);
    void installWorker(gp::ModelVersionPtr version);
    void installModel(gp::ModelVersionPtr version, bool adoptClip);
    // The current frame's point on `v`: the captured frame's start (learned_ik.h), or an edit's
    // point fitted on this model (edit/latent_refit.h); cached per frame, version and pose.
    const Eigen::VectorXd& frameLatent(const gp::ModelVersion& v) const;
    // Edited frame `frame` judged on version `v` without the model's score (the class steadying
    // compares); none on a captured frame or an edit without a latent point. Cached in judgedEdits_.
    std::optional<AdmissionVerdict> judgedEditAt(int frame, const gp::ModelVersionPtr& v) const;
    // currentPoseVerdict on version `v`.
    std::optional<AdmissionVerdict> poseVerdictOn(const gp::ModelVersionPtr& v) const;
    // The balance term's region for a drag of `dragged` from `pose` with these pins and planted feet.
    std::optional<BalanceRegion> dragBalance(Effector dragged, const Pose& pose, const std::vector<IkConstraint>& holds,
                                             const std::vector<IkConstraint>& feet) const;
    void setDragPins();  // a live drag's pins and balance region after a pin changed
    // Whether `pose` on `frame` is what the last drag left there, and what that drag reached.
    struct DragOutcome {
        bool lastDragged = false, reached = true, belowFloor = false;
    };
    DragOutcome dragOutcomeAt(int frame, const Pose& pose) const;
    // Posts an accepted pose to the adaptive worker, or keeps it for the final model while refining;
    // the sequence number of the post (0: none).
    long teach(AdaptiveSample sample, const Pose& edited, std::vector<Effector> moved);
    std::string undoOrRedo(bool undo);

    ClipEdits store_;
    int frame_ = 0;
    std::array<bool, kEffectorCount> pins_{};
    std::array<Eigen::Vector3d, kEffectorCount> pinPositions_{};
    std::array<bool, kEffectorCount> contactReleased_{};  // per foot, for drags (the contacts stay)

    gp::ModelVersionPtr compareModel_;
    EditHistory history_;
    std::atomic<long> revision_{0};
    // After revision_: its worker thread counts accepted updates there until it is destroyed.
    ModelHost models_{[this] { ++revision_; }};
    // Edits keep the x of their solve, which belongs to the model installed then: installModel
    // starts a new lineage (adaptive updates continue one), and each edited frame remembers its own.
    long lineage_ = 0;
    std::map<int, long> editLineage_;
    bool refining_ = false;
    std::vector<DeferredPose> deferred_;  // accepted while refining, oldest first

    PathSession paths_{store_.clip(), [this] { ++revision_; }};
    RegenerateJob regenerate_;
    std::optional<SpanQuality> lastRegenerateQuality_;
    std::vector<MotionEditJob::KeyResult> lastRegenerateKeys_;
    int falloffRadius_ = 0;  // set by setClip
    int spreadFalloff_ = 0;  // the running spread's falloff setting when it started
    int spreadRadius_ = 0;   // its radius: the falloff, or a whole-pose change's wider layer
    double bodyStiffness_ = 1.0;
    long falloffStepId_ = 0;      // the undo step a running falloff job merges into (0 = none)
    std::string falloffSkipped_;  // why the last change was not spread, until pollRegenerate says it

    std::set<int> keys_;
    // In-betweening jobs, one at a time. A job works on its own copy of the motion and the model
    // version, never on the document, so its thread may outlive the members declared after it.
    BackgroundWorker<InbetweenJob, InbetweenJob> fill_{
        WorkerPolicy::kLatestRequest,
        [](InbetweenJob& job, const std::atomic<bool>& cancel) -> JobOutcome<InbetweenJob> {
            job.cancel = &cancel;
            job.run();
            job.cancel = nullptr;
            if (job.cancelled) return {std::nullopt, "fill between keys cancelled"};
            return {std::move(job), ""};
        },
        "fill between keys failed: "};

    CompareMode compare_ = CompareMode::kNone;
    DragSession drag_;
    std::optional<EditRecord> dragBefore_;  // the frame's edit when the drag began (none = captured)
    int dragVersionBefore_ = 0;             // the model version when the drag began
    // Whether the last accepted drag reached its targets, and whether one was below the floor
    // (constraints are not kept with an edit).
    struct {
        int frame = -1;
        Pose pose;
        bool reached = true;
        bool belowFloor = false;
    } lastDrag_;
    std::optional<EditRecord> latentBefore_;

    // judgedEditAt's cache: a verdict per frame and the inputs it was judged from.
    struct JudgedEdit {
        const void* model = nullptr;
        int version = -1;
        const void* clipFrames = nullptr;
        std::vector<bool> contactsOn;
        Pose pose;
        std::vector<Effector> moved;
        bool reached = true, belowFloor = false;
        std::optional<AdmissionVerdict> verdict;
    };
    mutable std::map<int, JudgedEdit> judgedEdits_;

    // The current frame's latent point on the current model (frameLatent's cache).
    mutable int cacheFrame_ = -1, cacheVersion_ = -1;
    mutable const void* cacheModel_ = nullptr;
    mutable bool cacheEdited_ = false;
    mutable bool cacheCurrent_ = false;  // the edit's x belonged to the installed model
    mutable Pose cachePose_;             // the edit's pose the point was fitted to
    mutable Eigen::VectorXd cacheX_;
};

}  // namespace mgp
