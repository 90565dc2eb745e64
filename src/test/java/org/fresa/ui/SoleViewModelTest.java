package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.fresa.chart.PlotScene;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.fresa.sole.Foot;
import org.junit.jupiter.api.Test;

class SoleViewModelTest {

    @Test
    void everyMacroOfTheLibraryHasAPreviewOfItsThesisCall() {
        SoleViewModel vm = new SoleViewModel();
        assertEquals(18, vm.macros().size());
        for (String m : vm.macros()) {
            vm.selectMacro(m);
            assertTrue(vm.parametersText().startsWith(m), m);
            PlotScene s = vm.preview();
            assertEquals(m, s.title());
            boolean aux = m.equals("PRIM") || m.equals("NOVO");
            assertEquals(aux, s.layers().get(0).curves().isEmpty(), m);
        }
    }

    @Test
    void theSampleJobGivesItsSizesAndAPlotPerSizeAndFoot() throws Exception {
        SoleViewModel vm = new SoleViewModel();
        vm.load(JobXml.read(Path.of("samples/jobs/sole-men40.xml")));
        assertEquals("", vm.problem());
        assertEquals(java.util.List.of("38", "39", "40", "41", "42"), vm.sizes());
        assertEquals("40", vm.size());
        vm.selectSize("42");
        vm.selectFoot(Foot.LEFT);
        PlotScene s = vm.scene();
        assertTrue(s.title().contains("42") && s.title().contains("left"));
        assertFalse(s.layers().stream().filter(l -> l.style() == PlotScene.Style.FEED).findFirst().orElseThrow()
                .curves().isEmpty());
    }

    @Test
    void aJobWithoutSoleSettingsSaysSo() {
        SoleViewModel vm = new SoleViewModel();
        vm.load(Job.empty(JobTask.SOLE));
        assertTrue(vm.problem().contains("no sole settings"));
        assertTrue(vm.sizes().isEmpty());
    }
}
