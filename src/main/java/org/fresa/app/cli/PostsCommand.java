package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.post.NcPost;
import org.fresa.post.NcPosts;
import picocli.CommandLine.Command;

/** {@code fresa posts}: the post-processors. */
@Command(name = "posts", description = "List the post-processors.")
final class PostsCommand extends ListingCommand {

    @Override
    Map<String, Object> listing() {
        List<Map<String, Object>> posts = new ArrayList<>();
        for (NcPost p : NcPosts.all()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("name", p.name());
            m.put("description", p.description());
            m.put("default", p.name().equals(NcPosts.DEFAULT));
            posts.add(m);
        }
        Map<String, Object> all = new LinkedHashMap<>();
        all.put("posts", posts);
        return all;
    }

    @Override
    void print(Map<String, Object> listing, PrintWriter out) {
        for (NcPost p : NcPosts.all()) {
            out.printf("%-10s %s%n", p.name(), p.description());
        }
    }
}
