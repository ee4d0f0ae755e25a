package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.PoolExtension;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * {@link ShadowProgress} on real data (Big Tujunga, 1197 × 643): every algorithm and path reports growing counts
 * under one total, ending at the total, in many steps, and the mask is that of a computation without a listener.
 */
class ShadowProgressTest {

    @RegisterExtension
    static final PoolExtension POOL = new PoolExtension(2);

    private static Dem dem;

    @BeforeAll
    static void read() throws IOException {
        dem = DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"));
    }

    /** Updates heard, checked against the contract. */
    private static final class Recorder implements ShadowProgress {
        final List<long[]> updates = new ArrayList<>();

        @Override
        public synchronized void update(long done, long total) {
            updates.add(new long[] {done, total});
        }

        /** @return the count of values strictly between 0 and the total */
        int assertContract(String what) {
            assertTrue(!updates.isEmpty(), what + ": no progress");
            long total = updates.get(0)[1];
            long last = -1;
            int between = 0;
            for (long[] u : updates) {
                assertEquals(total, u[1], what + ": one total");
                assertTrue(u[0] >= last && u[0] <= total, what + ": grows within the total");
                last = u[0];
                between += u[0] > 0 && u[0] < total ? 1 : 0;
            }
            assertEquals(total, last, what + ": ends at the total");
            return between;
        }
    }

    private static void assertReports(ShadowAlgorithm a, ShadowOptions options, LightDirection light,
                                      int intermediate) {
        String what = a + " " + options;
        Recorder recorder = new Recorder();
        CellWindow whole = CellWindow.whole(dem.width(), dem.height());
        float[] heard = a.computeWindow(dem, light, options, POOL.get(), whole, recorder).backingArray();
        int between = recorder.assertContract(what);
        assertTrue(between >= intermediate, what + ": " + between + " intermediate values");
        assertArrayEquals(a.computeWindow(dem, light, options, POOL.get(), whole).backingArray(), heard, what);
    }

    @Test
    void everyAlgorithmReportsInManyStepsAndTheMaskIsUnchanged() {
        LightDirection low = new LightDirection(135, 12);
        assertReports(ShadowAlgorithm.SWEEP, ShadowOptions.DEFAULTS, low, 20);
        assertReports(ShadowAlgorithm.MARCH, ShadowOptions.DEFAULTS, low, 20);
        // soft shadows: all elevations across the disk in one walk, or level by level (thin features)
        assertReports(ShadowAlgorithm.SWEEP, ShadowOptions.DEFAULTS.withSoftShadows(true), low, 20);
        assertReports(ShadowAlgorithm.SWEEP, ShadowOptions.DEFAULTS.withSoftShadows(true).withThinFeatures(true),
                low, 20);
    }

    @Test
    void aMaskWithoutTracingReportsOneOfOne() {
        for (LightDirection light : new LightDirection[] {new LightDirection(135, 90), new LightDirection(135, -5)}) {
            Recorder recorder = new Recorder();
            ShadowAlgorithm.SWEEP.computeWindow(dem, light, ShadowOptions.DEFAULTS, POOL.get(),
                    CellWindow.whole(dem.width(), dem.height()), recorder);
            assertEquals(1, recorder.updates.size());
            assertArrayEquals(new long[] {1, 1}, recorder.updates.get(0));
        }
    }
}
