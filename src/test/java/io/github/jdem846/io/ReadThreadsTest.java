package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.DemTiles;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A large read runs in parts on threads of its own ({@code jdem846-read}); none of them outlives the call, whether
 * the read ends normally or is interrupted.
 */
class ReadThreadsTest {

    @TempDir
    static Path dir;

    /** Big Tujunga (real SRTM) mirrored to 3 × 3 its size: 6.9 M cells, read in parts. */
    private static Path largeGridFloat() throws Exception {
        Dem bt = TestDems.load(TestDems.BIG_TUJUNGA);
        Dem big = SyntheticDems.mirrored(bt, 3 * bt.width(), 3 * bt.height());
        Path flt = dir.resolve("bt3x3.flt");
        if (!flt.toFile().exists()) {
            DemTiles.gridFloat(big, List.of(new DemTiles.Cut(0, 0, big.width(), big.height())), dir, "bt3x3", null);
            java.nio.file.Files.move(dir.resolve("bt3x3_0.flt"), flt);
            java.nio.file.Files.move(dir.resolve("bt3x3_0.hdr"), dir.resolve("bt3x3.hdr"));
        }
        return flt;
    }

    private static long readThreadsAlive() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.isAlive() && t.getName().startsWith("jdem846-read")).count();
    }

    @Test
    void noReadingThreadOutlivesARead() throws Exception {
        Path flt = largeGridFloat();
        for (int i = 0; i < 3; i++) {
            Dem dem = DemReader.read(flt);
            assertEquals(3 * 1197, dem.width());
            assertEquals(0, readThreadsAlive(), "reading threads alive after read " + i);
        }
    }

    @Test
    void noReadingThreadOutlivesAnInterruptedRead() throws Exception {
        Path flt = largeGridFloat();
        for (long delayMs : new long[] {0, 2, 10, 40}) {
            AtomicReference<Throwable> outcome = new AtomicReference<>();
            Thread reader = new Thread(() -> {
                try {
                    DemReader.read(flt);
                } catch (Throwable t) {
                    outcome.set(t);
                }
            });
            reader.start();
            Thread.sleep(delayMs);
            reader.interrupt();
            reader.join(60_000);
            assertTrue(!reader.isAlive(), "the read returned");
            assertEquals(0, readThreadsAlive(), "reading threads alive after an interrupt at " + delayMs + " ms: "
                    + outcome.get());
        }
    }
}
