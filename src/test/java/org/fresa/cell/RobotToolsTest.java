package org.fresa.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.api.Test;

class RobotToolsTest {

    static ToolpathSection section(String label, int tool) {
        return new ToolpathSection(
                label, Vec3.UNIT_Z, 10, tool, 3000, Vec3.ZERO, List.of(new Move.Rapid(new Vec3(0, 0, 10))));
    }

    @Test
    void workingstepsSharingAnIdWithToolsOfDifferentLengthsGetALabelEach() {
        Transform3 t50 = RobotTools.tcp(Transform3.IDENTITY, 50);
        Transform3 t70 = RobotTools.tcp(Transform3.IDENTITY, 70);
        RobotTools.Frames f = RobotTools.labelled(
                Transform3.IDENTITY,
                List.of(section("hole", 1), section("hole", 2), section("pocket", 3), section("pocket", 3)),
                List.of(t50, t70, t70, t70),
                new ArrayList<>());
        List<String> labels =
                f.toolpath().sections().stream().map(ToolpathSection::label).toList();
        assertEquals(List.of("hole [T1]", "hole [T2]", "pocket", "pocket"), labels);
        assertEquals(50, f.tcpByLabel().get("hole [T1]").tz());
        assertEquals(70, f.tcpByLabel().get("hole [T2]").tz());
        assertEquals(70, f.tcpByLabel().get("pocket").tz());
    }
}
