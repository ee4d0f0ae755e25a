package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The up-front heap check of a picture: refused with its size, what it needs and the heap's maximum. */
class InsufficientHeapExceptionTest {

    @Test
    void aPictureTooLargeForTheHeapIsRefusedWithWhatItNeeds() {
        // grid 4 bytes per cell + ARGB picture 4 bytes per pixel: 40000 × 21487 needs 6.4 GiB
        InsufficientHeapException e = assertThrows(InsufficientHeapException.class,
                () -> InsufficientHeapException.requireFits(40_000L * 21_487, 40_000, 21_487, 4, 5L << 30));
        assertTrue(e.getMessage().contains("40000×21487") && e.getMessage().contains("6.4 GiB")
                && e.getMessage().contains("at most 5.0 GiB"), e.getMessage());
        // exactly the heap fits; the grid with a halo larger than the picture counts its own cells
        InsufficientHeapException.requireFits(1000 * 1000, 1000, 1000, 4, 8_000_000);
        assertThrows(InsufficientHeapException.class,
                () -> InsufficientHeapException.requireFits(1000 * 1001, 1000, 1000, 4, 8_000_000));
    }

    @Test
    void aPictureOfMoreCellsThanOneArrayIsRefusedInMemoryWhateverTheHeap() {
        InsufficientHeapException e = assertThrows(InsufficientHeapException.class,
                () -> InsufficientHeapException.requireFits(46_341L * 46_341, 46_341, 46_341, 1, Long.MAX_VALUE));
        assertTrue(e.getMessage().startsWith("a picture of 46341×46341 pixels from 2147488281 cells has more than"
                + " one Java array holds") && e.getMessage().endsWith("written to a file, it is rendered in tiles"),
                e.getMessage());
    }
}
