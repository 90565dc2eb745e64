package org.fresa.post;

import java.util.Optional;

/**
 * The posts the pocket module writes: the thesis's Sinumerik 7M dialect, as printed
 * ({@code 7m-compat}, the thesis's pass rules and programs character for character) or with its
 * defects corrected ({@code 7m}), then the posts of {@link MillingPost} (G-code and APT).
 */
public enum PocketPost {
    SINUMERIK_7M_COMPAT("7m-compat", null),
    SINUMERIK_7M("7m", null),
    LINUXCNC("linuxcnc", MillingPost.LINUXCNC),
    ISO("iso", MillingPost.ISO),
    FANUC("fanuc", MillingPost.FANUC),
    SIEMENS_840D("840d", MillingPost.SIEMENS_840D),
    APT("apt", MillingPost.APT);

    private final String word;
    private final MillingPost gcode;

    PocketPost(String word, MillingPost gcode) {
        this.word = word;
        this.gcode = gcode;
    }

    /** The name as the command line and job files write it. */
    public String word() {
        return word;
    }

    /** The G-code post, empty for the 7M dialect. */
    public Optional<MillingPost> gcode() {
        return Optional.ofNullable(gcode);
    }

    /** The extension of the program file: {@code nc} for the 7M dialect, otherwise the post's. */
    public String fileExtension() {
        return gcode == null ? "nc" : gcode.ncPost().fileExtension();
    }

    /** Whether this is the thesis's 7M dialect (no islands, micrometre coordinates). */
    public boolean sevenM() {
        return gcode == null;
    }

    /** Whether the thesis's programs are reproduced as printed (its pass rules and direction). */
    public boolean thesis() {
        return this == SINUMERIK_7M_COMPAT;
    }

    @Override
    public String toString() {
        return word;
    }
}
