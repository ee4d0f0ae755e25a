package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.PoolExtension;
import io.github.jdem846.testing.SyntheticDems;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/** {@link ShadowAlgorithm#computeCells}: the listed cells of a whole-grid computation, in the order given. */
class ShadowCellsTest {

    @RegisterExtension
    static final PoolExtension POOL = new PoolExtension(2);

    /** A rough DEM with a few no-data cells, so that sampled cells include no-data ones. */
    private static Dem dem() {
        Dem rough = SyntheticDems.rough(57, 43, 30, 11, 900);
        float[] v = rough.backingArray().clone();
        for (int i = 0; i < v.length; i += 37) {
            v[i] = Float.NaN;
        }
        return SyntheticDems.metric(57, 43, 30, v);
    }

    private static int[] randomCells(int n, int count, long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        int[] cells = new int[count];
        for (int q = 0; q < count; q++) {
            cells[q] = rnd.nextInt(n);
        }
        return cells;
    }

    @Test
    void listedCellsEqualTheWholeGridComputation() {
        Dem dem = dem();
        int[] cells = randomCells(dem.width() * dem.height(), 400, 846);
        ShadowOptions[] settings = {
            ShadowOptions.DEFAULTS,
            ShadowOptions.DEFAULTS.withStep(StepSize.HALF_CELL).withSampling(Sampling.BILINEAR),
            ShadowOptions.DEFAULTS.withStep(StepSize.ONE_CELL).withSampling(Sampling.NEAREST),
            ShadowOptions.DEFAULTS.withSoftShadows(true),
        };
        int shadowed = 0;
        for (ShadowAlgorithm alg : ShadowAlgorithm.values()) {
            for (ShadowOptions opt : settings) {
                for (double elevation : new double[] {-1, 4, 20, 90}) {
                    for (double azimuth : new double[] {160, 250}) {
                        LightDirection light = new LightDirection(azimuth, elevation);
                        float[] whole = alg.compute(dem, light, opt, POOL.get()).backingArray();
                        float[] listed = alg.computeCells(dem, light, opt, POOL.get(), cells);
                        assertEquals(cells.length, listed.length);
                        for (int q = 0; q < cells.length; q++) {
                            assertEquals(whole[cells[q]], listed[q], 0f, () -> alg + " " + opt + " " + light);
                            shadowed += listed[q] >= 0.5f ? 1 : 0;
                        }
                    }
                }
            }
        }
        assertTrue(shadowed > 1000, "the comparison covers shadowed cells too: " + shadowed);
    }

    @Test
    void emptyListAndBadIndices() {
        Dem dem = dem();
        LightDirection light = new LightDirection(250, 5);
        assertEquals(0, ShadowAlgorithm.EXACT.computeCells(dem, light, ShadowOptions.DEFAULTS, POOL.get(),
                new int[0]).length);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ShadowAlgorithm.MARCH.computeCells(dem, light, ShadowOptions.DEFAULTS, POOL.get(),
                        new int[] {0, 57 * 43}));
        assertTrue(e.getMessage().contains("2451"), e.getMessage());
    }
}
