package io.github.jdem846.testing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import org.junit.jupiter.api.Test;

class SyntheticDemsTest {

    @Test
    void fourQuarterTurnsGiveTheDemBackAndOneTurnMovesNorthToEast() {
        Dem dem = SyntheticDems.rough(7, 4, 30, 3, 200);
        Dem turned = SyntheticDems.rotateClockwise(dem);
        assertEquals(4, turned.width());
        assertEquals(7, turned.height());
        // the north-west corner goes to the north-east, the north-east corner to the south-east
        assertEquals(dem.get(0, 0), turned.get(3, 0));
        assertEquals(dem.get(6, 0), turned.get(3, 6));
        Dem back = turned;
        for (int k = 0; k < 3; k++) {
            back = SyntheticDems.rotateClockwise(back);
        }
        assertArrayEquals(dem.backingArray(), back.backingArray());
        assertEquals(dem.geometry(), back.geometry());
        Dem oblong = new Dem(new float[4], new GridGeometry(2, 2, 0, 4, 1, 2,
                CrsInfo.projected("local metric grid", null, 1.0, null), PixelAnchor.CORNER));
        assertThrows(IllegalArgumentException.class, () -> SyntheticDems.rotateClockwise(oblong));
    }

    @Test
    void mirroredTilesReflectAtEverySeamAndKeepTheSourceInPlace() {
        Dem source = TestDems.load(TestDems.VOLCANO);
        int w = source.width();
        int h = source.height();
        Dem big = SyntheticDems.mirrored(source, 2 * w + 5, 2 * h + 3);
        assertEquals(source.geometry().originX(), big.geometry().originX());
        assertEquals(source.geometry().originY(), big.geometry().originY());
        assertEquals(source.geometry().crs(), big.geometry().crs());
        for (int r = 0; r < big.height(); r++) {
            for (int c = 0; c < big.width(); c++) {
                int sc = c < w ? c : c < 2 * w ? 2 * w - 1 - c : c - 2 * w;
                int sr = r < h ? r : r < 2 * h ? 2 * h - 1 - r : r - 2 * h;
                assertEquals(source.get(sc, sr), big.get(c, r), "cell " + c + "," + r);
            }
        }
    }

    @Test
    void roughTerrainSpansItsReliefInSixteenthsOfAMetre() {
        Dem dem = SyntheticDems.rough(40, 30, 10, 5, 300);
        assertEquals(0, dem.statistics().min());
        assertEquals(300, dem.statistics().max(), 1.0 / 32);
        for (float z : dem.backingArray()) {
            assertTrue(z * 16 == Math.rint(z * 16), z + " is not a multiple of 1/16");
        }
    }
}
