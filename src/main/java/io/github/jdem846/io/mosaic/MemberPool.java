package io.github.jdem846.io.mosaic;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.source.RasterSource;
import java.io.Closeable;
import java.io.IOException;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The files of a mosaic that are open: a file is opened when a read first touches it, and at most {@code limit}
 * are open at once (the least recently read is closed first). A file whose header no longer matches the one
 * planned (changed since) is refused.
 */
final class MemberPool implements Closeable {

    private final MosaicPlan plan;
    private final int limit;
    private final LinkedHashMap<Integer, RasterSource> open = new LinkedHashMap<>(16, 0.75f, true);
    private int opens;

    MemberPool(MosaicPlan plan, int limit) {
        this.plan = plan;
        this.limit = Math.max(1, limit);
    }

    /** The open source of member {@code index}, opening it (and closing the least recently read) if needed. */
    RasterSource get(int index) throws IOException {
        RasterSource source = open.get(index);
        if (source != null) {
            return source;
        }
        while (open.size() >= limit) {
            Iterator<Map.Entry<Integer, RasterSource>> eldest = open.entrySet().iterator();
            RasterSource gone = eldest.next().getValue();
            eldest.remove();
            gone.close();
        }
        Member m = plan.members().get(index);
        source = plan.opener().open(m.header().given());
        opens++;
        DemInfo now = source.info();
        DemInfo then = m.header().info();
        if (now.width() != then.width() || now.height() != then.height() || now.format() != then.format()) {
            source.close();
            throw new DemFormatException(m.file(), "changed while it was being read: it is now " + now.width()
                    + " × " + now.height() + " cells of " + now.format().displayName() + ", its header said "
                    + then.width() + " × " + then.height() + " of " + then.format().displayName());
        }
        open.put(index, source);
        return source;
    }

    /** @return how many times a file was opened for its cells */
    int opens() {
        return opens;
    }

    /** @return how many files are open now */
    int openCount() {
        return open.size();
    }

    @Override
    public void close() throws IOException {
        IOException first = null;
        for (RasterSource s : open.values()) {
            try {
                s.close();
            } catch (IOException e) {
                if (first == null) {
                    first = e;
                }
            }
        }
        open.clear();
        if (first != null) {
            throw first;
        }
    }
}
