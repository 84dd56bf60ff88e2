// An edit's latent point follows the model (core/edit/latent_refit.h): the point a pose was solved
// at is kept while its model (or an adaptive update of it) is installed, and fitted again when
// another model is installed. The mirrored layout (X → −X) is the same GP (both kernels
// depend on x only through distances and angles between points), so the fitted point must be −x.
#include <doctest/doctest.h>

#include "document_helpers.h"
#include "edit/editor_document.h"
#include "edit/latent_refit.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE(
    "latent refit: a solved point is kept on its model, and on the mirrored layout the edit's point is fitted to -x") {
    EditorDocument doc;
    const gp::ModelVersionPtr v = test::walkModel35();
    doc.setModel(v, true);
    doc.setAdaptiveEnabled(false);
    doc.setFrame(99);
    test::dragBy(doc, Effector::kRHand, {5, 0, 0});
    doc.waitIdle();
    REQUIRE(doc.isEdited(99));
    const Eigen::VectorXd solved = doc.currentLatent();
    const std::optional<AdmissionVerdict> before = doc.currentPoseVerdict();
    REQUIRE(before.has_value());

    // Kept as it is on the model it was solved on.
    doc.setFrame(10);
    doc.setFrame(99);
    CHECK(doc.currentLatent() == solved);

    gp::GpModel mirrored = *v->model;
    mirrored.X = -mirrored.X;
    doc.setModel(gp::ModelVersion::make(std::move(mirrored)), false);
    doc.setFrame(99);
    const Eigen::VectorXd refitted = doc.currentLatent();
    INFO("solved " << solved.transpose() << ", refitted " << refitted.transpose());
    CHECK((refitted + solved).cwiseAbs().maxCoeff() <= 1e-3);
    const std::optional<AdmissionVerdict> after = doc.currentPoseVerdict();
    REQUIRE(after.has_value());
    CHECK(after->admitted == before->admitted);
    CHECK(after->lik == doctest::Approx(before->lik).epsilon(1e-4));
    CHECK(after->sigma2 == doctest::Approx(before->sigma2).epsilon(1e-4));
}
