package io.github.jdem846.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.raster.Dem;
import org.junit.jupiter.api.Test;

class TestDemsTest {
    @Test
    void fixtureRangesMatchProvenance() {
        // testdata/PROVENANCE.md summary table: min / max and no-data counts.
        Dem lux = TestDems.load(TestDems.LUXEMBOURG);
        assertEquals(3942, lux.statistics().noDataCount());
        assertEquals(141, lux.statistics().min());
        assertEquals(547, lux.statistics().max());
        Dem bt = TestDems.load(TestDems.BIG_TUJUNGA);
        assertEquals(315, bt.statistics().min());
        assertEquals(2295, bt.statistics().max());
        assertEquals(0, bt.statistics().noDataCount());
    }
}
