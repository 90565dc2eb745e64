package org.fresa.ui;

import java.io.File;
import java.nio.file.Path;
import javax.swing.JFileChooser;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The window's file choosers: every one starts in the folder the planner chose a file or folder
 * in last (at first the folder Fresa was started from), and offers the filter of its kind of file
 * first ("All files" stays one choice away).
 */
final class FileChoosers {

    /** The kinds of file the tabs open and save, each with its filter. */
    enum Kind {
        JOB("Fresa jobs (*.xml)", "xml"),
        STEPNC("STEP-NC Part 21 (*.stp, *.step, *.p21)", "stp", "step", "p21"),
        POCKET_CONTOUR("Pocket contours (*.dad, *.contour)", "dad", "contour"),
        DAD("Thesis pocket contours (*.dad)", "dad"),
        OUTLINE("Fresa contour (*.contour)", "contour"),
        DXF("DXF drawings (*.dxf)", "dxf"),
        ROBOT("Robot files (*.xml)", "xml"),
        TEXT("Text files (*.txt)", "txt"),
        NC_PROGRAM("NC programs (*.ngc, *.nc, *.mpf, *.apt, *.txt)", "ngc", "nc", "mpf", "apt", "txt"),
        PLOT("PNG image (*.png)", "png"),
        FOLDER(null);

        private final String description;
        private final String[] extensions;

        Kind(String description, String... extensions) {
            this.description = description;
            this.extensions = extensions;
        }
    }

    private static File folder = Path.of("").toAbsolutePath().toFile();

    private FileChoosers() {}

    /** A chooser of this kind in the remembered folder. Call on the event thread. */
    static JFileChooser chooser(Kind kind) {
        JFileChooser fc = new JFileChooser(folder);
        if (kind == Kind.FOLDER) {
            fc.setFileSelectionMode(JFileChooser.DIRECTORIES_ONLY);
        } else {
            if (kind == Kind.PLOT) {
                fc.addChoosableFileFilter(new FileNameExtensionFilter("SVG drawing (*.svg)", "svg"));
            }
            fc.setFileFilter(new FileNameExtensionFilter(kind.description, kind.extensions));
        }
        return fc;
    }

    /** Remembers the folder of what was chosen (the folder itself for a folder chooser) and returns it. */
    static Path chosen(JFileChooser fc) {
        File f = fc.getSelectedFile();
        boolean isFolder = fc.getFileSelectionMode() == JFileChooser.DIRECTORIES_ONLY;
        File dir = isFolder ? f : f.getParentFile();
        if (dir != null) {
            folder = dir;
        }
        return f.toPath();
    }

    /** The folder the next chooser starts in. */
    static Path folder() {
        return folder.toPath();
    }
}
