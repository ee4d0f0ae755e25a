package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.output.WriteOptions;
import org.junit.jupiter.api.Test;

/** How the output flags and {@code --threads} become {@link WriteOptions}. */
class OutputOptionsTest {

    private static ExecutionOptions threads(Integer n) {
        ExecutionOptions e = new ExecutionOptions();
        e.threads = n;
        return e;
    }

    @Test
    void oneWorkerThreadAlsoCompressesTheOutputOnOneThread() {
        OutputOptions out = new OutputOptions();
        assertFalse(out.writeOptions(threads(1)).parallelCompression(), "--threads 1: PNG and GeoTIFF on one thread");
        assertTrue(out.writeOptions(threads(4)).parallelCompression(), "--threads 4");
        assertEquals(Runtime.getRuntime().availableProcessors() > 1,
                out.writeOptions(threads(null)).parallelCompression(), "default: all processors");
    }

    @Test
    void worldFileFlagCarriesOverAndNoDataIsLeftToTheProduct() {
        OutputOptions out = new OutputOptions();
        assertEquals(WriteOptions.Sidecars.NONE, out.writeOptions(threads(2)).sidecars());
        assertNull(out.writeOptions(threads(2)).noData());
        out.worldFile = true;
        WriteOptions o = out.writeOptions(threads(2));
        assertEquals(WriteOptions.Sidecars.ALWAYS, o.sidecars());
        assertNull(o.noData(), "the product decides: a hillshade marks 0 (ReliefResult.write)");
    }
}
