package io.github.jdem846.output;

import java.nio.file.Path;
import java.util.List;

/**
 * What {@link ImageOutput} wrote.
 *
 * @param image    the image file
 * @param sidecars the world file, {@code .prj} and {@code .aux.xml} written, in that order (may be empty)
 * @param notices  things the user should be told, e.g. that no {@code .prj} was written because the CRS is unknown,
 *                 or that a stale sidecar of an earlier run was removed
 */
public record WriteResult(Path image, List<Path> sidecars, List<String> notices) {

    /**
     * Copies the lists.
     *
     * @param image the image file
     * @param sidecars the world file, {@code .prj} and {@code .aux.xml} written, in that order (may be empty)
     * @param notices things the user should be told, e.g. that no {@code .prj} was written because the CRS is unknown,
     *     or that a stale sidecar of an earlier run was removed
     */
    public WriteResult {
        sidecars = List.copyOf(sidecars);
        notices = List.copyOf(notices);
    }
}
