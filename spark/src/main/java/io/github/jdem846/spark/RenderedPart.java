package io.github.jdem846.spark;

import java.io.Serializable;
import java.util.HashMap;
import java.util.Map;

/**
 * What one task wrote: tiles by zoom and PNG bytes, summed on the driver for the report.
 *
 * @param writtenByZoom tiles written at each zoom
 * @param bytes         PNG bytes written
 */
record RenderedPart(Map<Integer, Long> writtenByZoom, long bytes) implements Serializable {

    private static final long serialVersionUID = 1L;

    RenderedPart {
        writtenByZoom = Map.copyOf(writtenByZoom);
    }

    /** @return both parts' counts together */
    RenderedPart plus(RenderedPart other) {
        Map<Integer, Long> sum = new HashMap<>(writtenByZoom);
        other.writtenByZoom.forEach((z, n) -> sum.merge(z, n, Long::sum));
        return new RenderedPart(sum, bytes + other.bytes);
    }

    /** @return tiles written at every zoom */
    long written() {
        return writtenByZoom.values().stream().mapToLong(Long::longValue).sum();
    }
}
