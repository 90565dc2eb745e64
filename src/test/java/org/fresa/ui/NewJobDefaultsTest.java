package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.ExactDecimal;
import org.junit.jupiter.api.Test;

/** A new job's tabs start from each module's defaults constant, as the command line and job.xsd do. */
class NewJobDefaultsTest {

    @Test
    void aNewPocketTabShowsThePocketDefaults() {
        PocketViewModel m = new PocketViewModel();
        PocketSettings d = PocketSettings.DEFAULTS;
        double[] v = {
            d.toolDiameterMm(),
            d.cutFraction(),
            d.finishFraction(),
            d.zTopMm(),
            d.zBottomMm(),
            d.maxDepthPerPassMm(),
            d.spindleRpm(),
            d.feedMmPerMin(),
            d.finishFeedMmPerMin()
        };
        assertAll(
                () -> assertEquals(d.post(), m.post()),
                () -> assertEquals(d.direction(), m.direction()),
                () -> assertEquals(d, m.settings()),
                () -> {
                    for (int i = 0; i < v.length; i++) {
                        assertEquals(ExactDecimal.of(v[i]), m.value(i), PocketViewModel.LABELS.get(i));
                    }
                });
    }

    @Test
    void aNewCuttingTabShowsTheCuttingDefaults() {
        CuttingViewModel m = new CuttingViewModel();
        CuttingSettings d = CuttingSettings.DEFAULTS;
        assertAll(
                () -> assertEquals(ExactDecimal.of(d.kerfMm()), m.kerfMm()),
                () -> assertEquals(d.process(), m.process()),
                () -> assertEquals(ExactDecimal.of(d.leadInMm()), m.leadInMm()),
                () -> assertEquals(ExactDecimal.of(d.leadOutMm()), m.leadOutMm()),
                () -> assertEquals(d.lead(), m.lead()),
                () -> assertEquals(d.post(), m.post()),
                () -> assertEquals(d.compensation(), m.compensation()),
                () -> assertEquals(d.outerDirection(), m.outerDirection()),
                () -> assertEquals(d.holeDirection(), m.holeDirection()),
                () -> assertEquals(ExactDecimal.of(d.overcutMm()), m.overcutMm()),
                () -> assertEquals(d.avoidCutParts(), m.avoidCutParts()),
                () -> assertEquals(d.paperMode(), m.paperMode()));
    }

    @Test
    void aNewGradingTabShowsTheGradingDefaults() {
        GradingViewModel m = new GradingViewModel();
        GradingSettings d = GradingSettings.DEFAULTS;
        assertAll(
                () -> assertEquals(d.system(), m.system()),
                () -> assertEquals(ExactDecimal.of(d.baseSize()), m.baseSize()),
                () -> assertEquals(d.sizes(), m.sizes()),
                () -> assertEquals(d.halfSizes(), m.halfSizes()),
                () -> assertEquals(ExactDecimal.of(d.shrinkage()), m.shrinkage()),
                () -> assertEquals(d.shrinkageMode(), m.shrinkageMode()),
                () -> assertEquals("", m.lengthStep()),
                () -> assertEquals("", m.widthStep()),
                () -> assertEquals("", m.origin()));
    }
}
