package io.github.jdem846.io.geotiff;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.raster.GridGeometry;
import java.util.ArrayList;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.metadata.IIOMetadata;

/**
 * What the tags of a GeoTIFF holding a picture (not elevations) say: its samples and, read as for a DEM ({@link
 * GeoTiffSource}), where it lies. For images draped over a relief ({@link io.github.jdem846.drape.DrapeImage}).
 *
 * @param geometry        the pixels' grid and CRS, or {@code null} when the file has no georeferencing tags
 * @param samplesPerPixel SamplesPerPixel (tag 277)
 * @param bitsPerSample   BitsPerSample (tag 258) of the first sample
 * @param photometric     PhotometricInterpretation (tag 262): 1 gray, 2 RGB, 3 palette, 6 YCbCr, …
 * @param notices         what was assumed while reading the tags
 */
public record GeoTiffImageTags(GridGeometry geometry, int samplesPerPixel, int bitsPerSample, int photometric,
                               List<String> notices) {

    /**
     * Copies the notices.
     *
     * @param geometry        the pixels' grid and CRS, or {@code null} when the file has no georeferencing tags
     * @param samplesPerPixel SamplesPerPixel (tag 277)
     * @param bitsPerSample   BitsPerSample (tag 258) of the first sample
     * @param photometric     PhotometricInterpretation (tag 262)
     * @param notices         what was assumed while reading the tags
     */
    public GeoTiffImageTags {
        notices = List.copyOf(notices);
    }

    /**
     * Reads the tags of a TIFF's first image from the metadata its TwelveMonkeys reader gives.
     *
     * @param tif      the file, named in messages
     * @param metadata the first image's metadata ({@code ImageReader.getImageMetadata(0)})
     * @param width    the image's width in pixels
     * @param height   the image's height in pixels
     * @return the tags
     * @throws DemFormatException when the georeferencing tags are present but unusable (rotated, flipped, too few
     *                            values); the message names the file and the tag
     */
    public static GeoTiffImageTags read(Path tif, IIOMetadata metadata, int width, int height)
            throws DemFormatException {
        TiffFields fields = TiffFields.of(metadata);
        boolean georeferenced = fields.has(TiffFields.MODEL_TRANSFORMATION)
                || fields.has(TiffFields.MODEL_TIEPOINT) && fields.has(TiffFields.MODEL_PIXEL_SCALE);
        List<String> notices = new ArrayList<>();
        GridGeometry geometry;
        try {
            geometry = georeferenced ? GeoTiffTags.geometry(tif, fields, width, height, notices) : null;
        } catch (IllegalArgumentException e) {
            throw new DemFormatException(tif, e.getMessage());
        }
        int bits = fields.has(TiffFields.BITS_PER_SAMPLE) ? (int) fields.longs(TiffFields.BITS_PER_SAMPLE)[0] : 1;
        return new GeoTiffImageTags(geometry, fields.intValue(TiffFields.SAMPLES_PER_PIXEL, 1), bits,
                fields.intValue(TiffFields.PHOTOMETRIC, -1), notices);
    }
}
