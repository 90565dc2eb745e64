package org.fresa.post;

import java.util.Locale;

/**
 * The machine-tool posts of {@link NcPosts} as a setting: {@code linuxcnc} (the default),
 * {@code iso}, {@code fanuc}, {@code 840d}, and the APT / CL-data post {@code apt}.
 */
public enum MillingPost {
    LINUXCNC("linuxcnc"),
    ISO("iso"),
    FANUC("fanuc"),
    SIEMENS_840D("840d"),
    APT("apt");

    private final String word;

    MillingPost(String word) {
        this.word = word;
    }

    /** The name as the command line and job files write it. */
    public String word() {
        return word;
    }

    /** The post that writes the programs. */
    public NcPost ncPost() {
        return NcPosts.byName(word).orElseThrow();
    }

    /** The post of a registered name (ignoring case), for callers that hold a name. */
    public static java.util.Optional<MillingPost> of(String name) {
        String n = name.trim().toLowerCase(Locale.ROOT);
        for (MillingPost p : values()) {
            if (p.word.equals(n)) {
                return java.util.Optional.of(p);
            }
        }
        return java.util.Optional.empty();
    }

    @Override
    public String toString() {
        return word;
    }
}
