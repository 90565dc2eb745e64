package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.JFileChooser;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FileChoosersTest {

    @TempDir
    Path dir;

    @Test
    void everyChooserStartsWhereTheLastChoiceWasMadeWithItsKindsFilter() throws Exception {
        Path parts = Files.createDirectories(dir.resolve("parts"));
        Path drawing = Files.writeString(parts.resolve("plate.dxf"), "");
        JFileChooser[] made = new JFileChooser[3];
        SwingUtilities.invokeAndWait(() -> {
            JFileChooser dxf = FileChoosers.chooser(FileChoosers.Kind.DXF);
            dxf.setSelectedFile(drawing.toFile());
            FileChoosers.chosen(dxf);
            made[0] = FileChoosers.chooser(FileChoosers.Kind.STEPNC);
            made[1] = FileChoosers.chooser(FileChoosers.Kind.FOLDER);
            made[2] = FileChoosers.chooser(FileChoosers.Kind.PLOT);
        });
        JFileChooser stepnc = made[0];
        assertAll(
                () -> assertEquals(
                        parts.toFile().getCanonicalFile(),
                        stepnc.getCurrentDirectory().getCanonicalFile()),
                () -> assertEquals(
                        parts.toFile().getCanonicalFile(),
                        made[1].getCurrentDirectory().getCanonicalFile()),
                () -> assertTrue(stepnc.getFileFilter().accept(new File("part.stp"))),
                () -> assertFalse(stepnc.getFileFilter().accept(new File("plate.dxf"))),
                () -> assertEquals(JFileChooser.DIRECTORIES_ONLY, made[1].getFileSelectionMode()),
                () -> assertTrue(made[2].getFileFilter().accept(new File("plot.png"))),
                () -> assertEquals(3, made[2].getChoosableFileFilters().length, "all files, SVG and PNG"));
    }
}
