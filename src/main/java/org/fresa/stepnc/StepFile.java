package org.fresa.stepnc;

import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * A whole Part 21 exchange structure: the header records and the instances of every data section,
 * in file order, by name. References are checked: every {@link StepValue.Ref} names an instance
 * of this file.
 *
 * <p>The instances are held in a compact coded form and decoded each time they are asked for, so
 * a 100 MB file fits in a small heap; {@link StepInstance}s obtained from here are values, equal
 * from one call to the next but not the same objects.
 */
public final class StepFile {

    private final String source;
    private final List<StepRecord> header;
    private final InstanceStore store;
    private final Map<Long, StepInstance> view = new InstancesView();

    StepFile(String source, List<StepRecord> header, InstanceStore store) {
        this.source = Objects.requireNonNull(source, "source");
        this.header = List.copyOf(header);
        this.store = Objects.requireNonNull(store, "store");
    }

    /** The file name used in messages. */
    public String source() {
        return source;
    }

    /** The header records (FILE_DESCRIPTION, FILE_NAME, FILE_SCHEMA, ...). */
    public List<StepRecord> header() {
        return header;
    }

    /** The instances by name, in file order: an unmodifiable view that decodes on access. */
    public Map<Long, StepInstance> instances() {
        return view;
    }

    public Optional<StepInstance> instance(long id) {
        int i = store.indexOf(id);
        return i < 0 ? Optional.empty() : Optional.of(store.instanceAt(i));
    }

    /** Number of instances. */
    public int size() {
        return store.count();
    }

    /** The name of the i-th instance in file order. */
    long idAt(int i) {
        return store.idAt(i);
    }

    /** The index in file order of instance #id, or -1. */
    int indexOf(long id) {
        return store.indexOf(id);
    }

    boolean isComplexAt(int i) {
        return store.isComplexAt(i);
    }

    /** The keyword of the (first) record of the i-th instance, without decoding it. */
    String firstTypeAt(int i) {
        return store.firstTypeAt(i);
    }

    StepInstance instanceAt(int i) {
        return store.instanceAt(i);
    }

    /**
     * The same file with only the instances named: what stays of a large file once it is bound,
     * when later steps read only these few instances and the rest of the table would be most of
     * the memory. References to the instances left out are kept as written.
     */
    public StepFile only(java.util.Set<Long> ids) {
        InstanceStore kept = new InstanceStore();
        for (int i = 0; i < store.count(); i++) {
            if (ids.contains(store.idAt(i))) {
                StepInstance inst = store.instanceAt(i);
                kept.beginInstance(inst.id(), inst.line(), inst.column(), inst.isComplex());
                for (StepRecord r : inst.records()) {
                    kept.putString(InstanceStore.RECORD, r.type());
                    encodeList(kept, r.params(), inst.id());
                }
            }
        }
        return new StepFile(source, header, kept);
    }

    /** A list as the reader codes it: begin, its items, end. */
    private static void encodeList(InstanceStore to, List<StepValue> items, long self) {
        to.put(InstanceStore.BEGIN);
        for (StepValue v : items) {
            encode(to, v, self);
        }
        to.put(InstanceStore.END);
    }

    private static void encode(InstanceStore to, StepValue v, long self) {
        if (v instanceof StepValue.Unset) {
            to.put(InstanceStore.UNSET);
        } else if (v instanceof StepValue.Derived) {
            to.put(InstanceStore.DERIVED);
        } else if (v instanceof StepValue.Int n) {
            to.putSigned(InstanceStore.INT, n.value());
        } else if (v instanceof StepValue.Real r) {
            to.putReal(r.value());
        } else if (v instanceof StepValue.Text t) {
            to.putString(InstanceStore.TEXT, t.value());
        } else if (v instanceof StepValue.Enumeration e) {
            to.putString(InstanceStore.ENUM, e.name());
        } else if (v instanceof StepValue.Binary b) {
            to.putString(InstanceStore.BINARY, b.hex());
        } else if (v instanceof StepValue.Ref ref) {
            to.putSigned(InstanceStore.REF, ref.id() - self);
        } else if (v instanceof StepValue.Aggregate a) {
            encodeList(to, a.items(), self);
        } else if (v instanceof StepValue.Typed t) {
            to.putString(InstanceStore.TYPED, t.type());
            encode(to, t.value(), self);
        } else {
            throw new IllegalStateException("no code for " + v);
        }
    }

    /** The schema names of FILE_SCHEMA, upper case; empty when the header has none. */
    public List<String> schemas() {
        List<String> out = new ArrayList<>();
        for (StepRecord r : header) {
            if (r.type().equals("FILE_SCHEMA") && r.param(0) instanceof StepValue.Aggregate a) {
                for (StepValue v : a.items()) {
                    if (v instanceof StepValue.Text t) {
                        out.add(t.value().toUpperCase(java.util.Locale.ROOT));
                    }
                }
            }
        }
        return out;
    }

    /** A header text attribute, e.g. FILE_NAME's preprocessor_version (index 4). */
    public Optional<String> headerText(String record, int index) {
        for (StepRecord r : header) {
            if (r.type().equals(record) && r.param(index) instanceof StepValue.Text t) {
                return Optional.of(t.value());
            }
        }
        return Optional.empty();
    }

    @Override
    public String toString() {
        return "StepFile[" + source + ", " + store.count() + " instances]";
    }

    private final class InstancesView extends AbstractMap<Long, StepInstance> {
        @Override
        public int size() {
            return store.count();
        }

        @Override
        public boolean containsKey(Object key) {
            return key instanceof Long id && store.indexOf(id) >= 0;
        }

        @Override
        public StepInstance get(Object key) {
            if (!(key instanceof Long id)) {
                return null;
            }
            int i = store.indexOf(id);
            return i < 0 ? null : store.instanceAt(i);
        }

        @Override
        public Set<Entry<Long, StepInstance>> entrySet() {
            return new AbstractSet<>() {
                @Override
                public int size() {
                    return store.count();
                }

                @Override
                public Iterator<Entry<Long, StepInstance>> iterator() {
                    return new Iterator<>() {
                        private int i;

                        @Override
                        public boolean hasNext() {
                            return i < store.count();
                        }

                        @Override
                        public Entry<Long, StepInstance> next() {
                            if (i >= store.count()) {
                                throw new NoSuchElementException();
                            }
                            int k = i++;
                            return new SimpleImmutableEntry<>(store.idAt(k), store.instanceAt(k));
                        }
                    };
                }
            };
        }
    }
}
