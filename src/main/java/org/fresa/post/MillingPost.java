package org.fresa.post;

import java.util.Locale;
import org.fresa.model.EnumWords;
import org.fresa.model.WordedEnum;

/**
 * The machine-tool posts of {@link NcPosts} as a setting: {@code linuxcnc} (the default),
 * {@code iso}, {@code fanuc}, {@code 840d}, and the APT / CL-data post {@code apt}.
 */
public enum MillingPost implements WordedEnum {
    LINUXCNC("linuxcnc"),
    ISO("iso"),
    FANUC("fanuc"),
    SIEMENS_840D("840d"),
    APT("apt");

    private final String word;

    MillingPost(String word) {
        this.word = word;
    }

    /** The name as the command line and job files write it: the post's own, not the constant's. */
    @Override
    public String word() {
        return word;
    }

    /** The post that writes the programs. */
    public NcPost ncPost() {
        return NcPosts.byName(word).orElseThrow();
    }

    /** The post of a registered name (ignoring case), for callers that hold a name. */
    public static java.util.Optional<MillingPost> of(String name) {
        return EnumWords.parse(MillingPost.class, MillingPost::word, name.trim().toLowerCase(Locale.ROOT));
    }

    @Override
    public String toString() {
        return word;
    }
}
