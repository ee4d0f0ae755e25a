package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

class ImageFormatTest {

    @Test
    void formatComesFromTheExtensionInAnyCase() {
        assertEquals(ImageFormat.PNG, ImageFormat.of(Path.of("out/relief.png")));
        assertEquals(ImageFormat.PNG, ImageFormat.of(Path.of("RELIEF.PNG")));
        assertEquals(ImageFormat.GEOTIFF, ImageFormat.of(Path.of("a.b.tif")));
        assertEquals(ImageFormat.GEOTIFF, ImageFormat.of(Path.of("x.TIFF")));
        assertEquals(ImageFormat.JPEG, ImageFormat.of(Path.of("x.jpg")));
        assertEquals(ImageFormat.JPEG, ImageFormat.of(Path.of("x.JPEG")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"relief.gif", "relief", "relief.png.bak", ".png", "relief.tif.", "dir/"})
    void unknownExtensionsAreRejectedWithTheSupportedList(String name) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ImageFormat.of(Path.of(name)));
        assertTrue(e.getMessage().contains(".png, .tif, .tiff, .jpg, .jpeg"), e.getMessage());
    }

    @Test
    void worldFileExtensionsFollowTheEsriConvention() {
        assertEquals("pgw", ImageFormat.PNG.worldFileExtension());
        assertEquals("tfw", ImageFormat.GEOTIFF.worldFileExtension());
        assertEquals("jgw", ImageFormat.JPEG.worldFileExtension());
    }
}
