package org.fresa.stepnc;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The entities the ISO 14649 binding supports and their attribute order, loaded once from the
 * EXPRESS-like subset {@code schemas/iso14649-subset.exp} on the classpath. Subtypes list their
 * supertypes' attributes first; {@code --@alias} remarks add the other spellings real files use.
 */
public final class Iso14649Schema {

    /** The resource the schema is read from. */
    public static final String RESOURCE = "/schemas/iso14649-subset.exp";

    private static final Pattern ENTITY =
            Pattern.compile("ENTITY\\s+(\\w+)([^;]*);(.*?)END_ENTITY\\s*;([ \\t]*--@alias\\s+(\\w+))?", Pattern.DOTALL);
    private static final Pattern SUBTYPE = Pattern.compile("SUBTYPE\\s+OF\\s*\\(\\s*(\\w+)\\s*\\)");
    private static final Pattern ATTRIBUTE = Pattern.compile("(\\w+)\\s*:[^;]*;");

    private static final Iso14649Schema INSTANCE = load();

    private final Map<String, EntityDef> byName;
    private final Map<String, String> aliases;

    private Iso14649Schema(Map<String, EntityDef> byName, Map<String, String> aliases) {
        this.byName = Collections.unmodifiableMap(byName);
        this.aliases = Collections.unmodifiableMap(aliases);
    }

    public static Iso14649Schema get() {
        return INSTANCE;
    }

    /**
     * One entity of the subset.
     *
     * @param name upper case, as files write it
     * @param isAbstract abstract supertypes never appear in files
     * @param attributes all attribute names, inherited ones first, in file order
     * @param ancestors this entity and all its supertypes, upper case
     */
    public record EntityDef(String name, boolean isAbstract, List<String> attributes, Set<String> ancestors) {
        public EntityDef {
            attributes = List.copyOf(attributes);
            ancestors = Collections.unmodifiableSet(new LinkedHashSet<>(ancestors));
        }

        /** The position of an attribute, or -1. */
        public int indexOf(String attribute) {
            // the names are interned and the binder asks with literals: identity finds them without
            // comparing the characters of every attribute before
            for (int i = 0, n = attributes.size(); i < n; i++) {
                if (attributes.get(i) == attribute) {
                    return i;
                }
            }
            return attributes.indexOf(attribute);
        }

        public boolean isA(String supertype) {
            return ancestors.contains(supertype);
        }
    }

    /**
     * An entity name looked up: the definition and, for an alias, the name it stands for.
     *
     * @param spelling the name as the file writes it
     */
    public record Lookup(EntityDef def, String spelling) {
        public boolean isAlias() {
            return !def.name().equals(spelling);
        }
    }

    // the answers by name as written: a file repeats a few hundred names many times
    private final Map<String, Optional<Lookup>> found = new java.util.concurrent.ConcurrentHashMap<>();

    public Optional<Lookup> find(String entityName) {
        Optional<Lookup> l = found.get(entityName);
        if (l == null) {
            l = lookUp(entityName);
            if (found.size() < 10_000) {
                found.put(entityName, l);
            }
        }
        return l;
    }

    private Optional<Lookup> lookUp(String entityName) {
        String upper = entityName.toUpperCase(Locale.ROOT);
        EntityDef d = byName.get(upper);
        if (d == null) {
            String target = aliases.get(upper);
            if (target != null) {
                d = byName.get(target);
            }
        }
        return d == null || d.isAbstract() ? Optional.empty() : Optional.of(new Lookup(d, upper));
    }

    /** Every concrete entity name and alias the binding accepts. */
    public Set<String> acceptedNames() {
        Set<String> out = new java.util.TreeSet<>();
        byName.values().stream().filter(d -> !d.isAbstract()).forEach(d -> out.add(d.name()));
        out.addAll(aliases.keySet());
        return out;
    }

    private static Iso14649Schema load() {
        try (InputStream in = Iso14649Schema.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException(RESOURCE + " is missing from the classpath");
            }
            return parse(new String(in.readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static Iso14649Schema parse(String text) {
        String clean = text.replaceAll("(?s)\\(\\*.*?\\*\\)", " ");
        Map<String, String> supertypeOf = new HashMap<>();
        Map<String, List<String>> own = new HashMap<>();
        Map<String, Boolean> abstracts = new HashMap<>();
        Map<String, String> aliases = new HashMap<>();
        List<String> order = new ArrayList<>();
        Matcher m = ENTITY.matcher(clean);
        while (m.find()) {
            // interned, as the attribute names: isA is asked with literals, and the set then
            // finds them on identity
            String name = m.group(1).toUpperCase(Locale.ROOT).intern();
            String head = m.group(2);
            abstracts.put(name, head.contains("ABSTRACT"));
            Matcher s = SUBTYPE.matcher(head);
            if (s.find()) {
                supertypeOf.put(name, s.group(1).toUpperCase(Locale.ROOT).intern());
            }
            List<String> attrs = new ArrayList<>();
            Matcher a = ATTRIBUTE.matcher(m.group(3).replaceAll("--[^\n]*", ""));
            while (a.find()) {
                // interned: the binder asks with literals, so equals succeeds on identity
                attrs.add(a.group(1).toLowerCase(Locale.ROOT).intern());
            }
            own.put(name, attrs);
            if (m.group(5) != null) {
                aliases.put(m.group(5).toUpperCase(Locale.ROOT), name);
            }
            order.add(name);
        }
        Map<String, EntityDef> defs = new HashMap<>();
        for (String name : order) {
            List<String> chain = new ArrayList<>();
            String cur = name;
            while (cur != null) {
                if (chain.contains(cur) || !own.containsKey(cur)) {
                    throw new IllegalStateException("schema: bad supertype chain at " + cur);
                }
                chain.add(cur);
                cur = supertypeOf.get(cur);
            }
            List<String> attrs = new ArrayList<>();
            for (int i = chain.size() - 1; i >= 0; i--) {
                attrs.addAll(own.get(chain.get(i)));
            }
            defs.put(name, new EntityDef(name, abstracts.get(name), attrs, new LinkedHashSet<>(chain)));
        }
        return new Iso14649Schema(defs, aliases);
    }
}
