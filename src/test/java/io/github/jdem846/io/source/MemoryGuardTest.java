package io.github.jdem846.io.source;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemFormatException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class MemoryGuardTest {

    private static final long HEAP = Runtime.getRuntime().maxMemory();

    @Test
    void smallGridsFitAndWorkBuffersCount() {
        assertTrue(MemoryGuard.fits(100, 100, 0));
        // The grid alone fits, but not with working buffers larger than the whole heap (e.g. one band per thread).
        assertFalse(MemoryGuard.fits(100, 100, HEAP));
        assertFalse(MemoryGuard.fits(65_536, 65_536, 0), "2³² cells exceed one Java array");
    }

    @Test
    void requireFitsNamesTheFileAndTheSizes() {
        DemFormatException e = assertThrows(DemFormatException.class,
                () -> MemoryGuard.requireFits(Path.of("big.tif"), 1000, 1000, HEAP, "read a window"));
        assertTrue(e.getMessage().contains("big.tif") && e.getMessage().contains("1000 × 1000")
                && e.getMessage().contains("read a window"), e.getMessage());
    }
}
