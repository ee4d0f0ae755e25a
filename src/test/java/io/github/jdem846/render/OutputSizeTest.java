package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.Window;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.GridRequestException;
import org.junit.jupiter.api.Test;

/**
 * Output sizes are computed in long and checked before anything is allocated: at most {@link OutputSize#MAX_SIDE}
 * pixels per side and {@link OutputSize#MAX_PIXELS} in all, at least one pixel per side for a scale. What depends on
 * the grid is a {@link GridRequestException} naming the grid's size; the rest an IllegalArgumentException.
 */
class OutputSizeTest {

    @Test
    void sidesAndScalesOutOfRangeAreRefusedWithTheRange() {
        for (int bad : new int[] {0, -1, OutputSize.MAX_SIDE + 1, Integer.MAX_VALUE}) {
            String m = assertThrows(IllegalArgumentException.class, () -> OutputSize.width(bad)).getMessage();
            assertTrue(m.contains("1 to 100000") && m.contains("got " + bad), m);
            assertThrows(IllegalArgumentException.class, () -> OutputSize.height(bad));
        }
        for (double bad : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY, 1e6}) {
            String m = assertThrows(IllegalArgumentException.class, () -> OutputSize.scale(bad)).getMessage();
            assertTrue(m.contains("above 0 and at most 100000") && m.contains("got " + bad), m);
            assertThrows(IllegalArgumentException.class, () -> new OutputSize(0, 0, bad == 0 ? -1 : bad));
        }
        String both = assertThrows(IllegalArgumentException.class,
                () -> new OutputSize(100_000, 100_000, 0)).getMessage();
        assertTrue(both.contains("10000000000 pixels") && both.contains("2147483639"), both);
        assertEquals(OutputSize.MAX_SIDE, OutputSize.width(OutputSize.MAX_SIDE).width());
    }

    @Test
    void aWidthWhoseHeightOverflowsAnIntArrayIsRefusedNotWrapped() {
        // 100000 × 53718 = 5.4e9 pixels, more than an int can count
        GridRequestException e = assertThrows(GridRequestException.class,
                () -> OutputSize.width(100_000).pixelsFor(1197, 643));
        assertEquals(GridRequestException.Part.SIZE, e.part());
        assertTrue(e.getMessage().contains("100000×53718") && e.getMessage().contains("1197×643")
                && e.getMessage().contains("2147483639 in all"), e.getMessage());
        assertThrows(GridRequestException.class, () -> OutputSize.height(100_000).pixelsFor(1000, 10));
        assertThrows(GridRequestException.class, () -> OutputSize.scale(100_000).pixelsFor(2, 1));
        assertArrayEquals(new int[] {100_000, 21_000}, OutputSize.width(100_000).pixelsFor(1000, 210));
    }

    @Test
    void aScaleMustLeaveAPixelOnEachSide() {
        GridRequestException e = assertThrows(GridRequestException.class,
                () -> OutputSize.scale(1e-9).pixelsFor(1197, 643));
        assertTrue(e.getMessage().contains("1197×643") && e.getMessage().contains("0.000778"), e.getMessage());
        assertArrayEquals(new int[] {1, 1}, OutputSize.scale(0.000778).pixelsFor(1197, 643));
        assertThrows(GridRequestException.class, () -> OutputSize.scale(0.00077).pixelsFor(1197, 643));
        // a width or height asked for keeps at least one pixel on the other side
        assertArrayEquals(new int[] {1, 1}, OutputSize.width(1).pixelsFor(5000, 10));
        assertArrayEquals(new int[] {1197, 643}, OutputSize.FULL.pixelsFor(1197, 643));
    }

    @Test
    void aWindowOutsideTheGridIsAGridRequestException() {
        GridGeometry g = GridGeometry.metric(100, 50, 10);
        GridRequestException cells = assertThrows(GridRequestException.class,
                () -> Window.cells(90, 0, 20, 10).resolve(g));
        assertEquals(GridRequestException.Part.WINDOW, cells.part());
        assertTrue(cells.getMessage().contains("100×50"), cells.getMessage());
        GridRequestException world = assertThrows(GridRequestException.class,
                () -> Window.world(-100, -100, -50, -50).resolve(g));
        assertEquals(GridRequestException.Part.WINDOW, world.part());
        assertTrue(world.getMessage().contains("east 1000.0, north 500.0"), world.getMessage());
    }
}
