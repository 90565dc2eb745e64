package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

class StepNcViewModelTest {

    static StepNcViewModel loaded(String name) throws Exception {
        StepNcViewModel vm = new StepNcViewModel();
        vm.load(StepNcReader.read(Path.of("samples/stepnc", name)));
        return vm;
    }

    @Test
    void theTreeShowsWorkplansThenSkippedWorkingstepsAndNotes() throws Exception {
        StepNcViewModel.Node root = loaded("example2.stp").tree().orElseThrow();
        assertTrue(root.label().contains("3caras"));
        List<String> top = root.children().stream().map(StepNcViewModel.Node::label).toList();
        assertEquals("Workplan 'Main workplan'", top.get(0));
        assertEquals("Skipped workingsteps (14)", top.get(1));
        StepNcViewModel.Node main = root.children().get(0);
        assertEquals(3, main.children().size());
        assertEquals(9, main.children().get(0).children().size());
        assertTrue(main.children().get(0).children().get(0).workingstep().isPresent());
        assertTrue(main.children().get(0).children().get(0).label().startsWith("1. "));
    }

    @Test
    void unknownEntitiesAreVisibleInTheTree() throws Exception {
        StepNcViewModel.Node root = loaded("iso14649-11-example1-explicit-toolpaths.stp").tree().orElseThrow();
        assertTrue(root.children().stream().anyMatch(n -> n.label().startsWith("Entities not interpreted")),
                root.children().toString());
    }

    @Test
    void theDetailsGiveUnits() throws Exception {
        StepNcViewModel vm = loaded("iso14649-11-example1.stp");
        String text = String.join("\n", vm.details());
        assertTrue(text.contains("PLANAR_FACE"), text);
        assertTrue(text.contains("depth 5 mm"), text);
        assertTrue(text.contains("feed 0.04 m/s = 2400 mm/min"), text);
        assertTrue(text.contains("= 720 rpm, clockwise"), text);
        assertTrue(text.contains("diameter 18 mm"), text);
    }

    @Test
    void aHoleOnTheFrontFaceIsDrawnAsACircleInTheFrontView() throws Exception {
        StepNcViewModel vm = loaded("example2.stp");
        StepNcProgram p = vm.program().orElseThrow();
        MachiningWorkingstep hole = p.workingsteps().get(11);
        vm.select(Optional.of(hole));
        PlotScene s = vm.plot();
        assertEquals("Front view (XZ)", s.title());
        PlotScene.Layer feature = s.layers().get(1);
        Arc2 circle = (Arc2) feature.curves().get(0);
        assertEquals(60.0, circle.center().x(), 1e-9);
        assertEquals(150.0, circle.center().y(), 1e-9);
        Box2 all = s.bounds().orElseThrow();
        assertEquals(200.0, all.width(), 1e-9);
    }

    @Test
    void theTopPocketIsDrawnAsItsRectangle() throws Exception {
        StepNcViewModel vm = loaded("example2.stp");
        vm.select(Optional.of(vm.program().orElseThrow().workingsteps().get(8)));
        PlotScene s = vm.plot();
        assertEquals("Top view (XY)", s.title());
        assertEquals(4, s.layers().get(1).curves().size());
        var b = s.layers().get(1).curves().get(0).bounds();
        assertEquals(30.0, b.minX(), 1e-9);
    }
}
