package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.fresa.io.Json;
import org.fresa.post.NcPost;
import org.fresa.post.NcPosts;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fresa posts}: the post-processors. */
@Command(name = "posts", mixinStandardHelpOptions = true, description = "List the post-processors.")
final class PostsCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--json", description = "print as JSON")
    boolean json;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        List<Map<String, Object>> posts = new ArrayList<>();
        for (NcPost p : NcPosts.all()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("name", p.name());
            m.put("description", p.description());
            m.put("default", p.name().equals(NcPosts.DEFAULT));
            posts.add(m);
        }
        if (json) {
            Map<String, Object> all = new LinkedHashMap<>();
            all.put("posts", posts);
            out.println(Json.write(all));
        } else {
            for (NcPost p : NcPosts.all()) {
                out.printf("%-10s %s%n", p.name(), p.description());
            }
        }
        out.flush();
        return CliSupport.EXIT_OK;
    }
}
