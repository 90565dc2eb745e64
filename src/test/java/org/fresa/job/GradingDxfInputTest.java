package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.dxf.DxfWriter;
import org.fresa.geom.Contour;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class GradingDxfInputTest {

    @TempDir
    Path dir;

    @Test
    void aDxfOutlineReadsAsTheSameContourAsItsContourFile() throws Exception {
        List<Contour> base = GradingService.readOutline(Path.of("samples/grading/sole-40.contour"));
        Path dxf = dir.resolve("sole-40.dxf");
        Files.writeString(dxf, DxfWriter.write(base, "OUTLINE"));
        List<Contour> back = GradingService.readOutline(dxf);
        assertEquals(1, back.size());
        assertEquals(base.get(0).area(), back.get(0).area(), 1e-6);
        assertEquals(base.get(0).bounds().height(), back.get(0).bounds().height(), 1e-9);
    }
}
