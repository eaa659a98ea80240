package lt.spindulys.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.SceneBuilder;

/**
 * One bench view as the peer renderers are told it: a pinhole camera, one point light with
 * inverse-square falloff, the image size and the OBJ meshes (grey Lambert 0.8, flat normals,
 * 1 sample per pixel, direct light only, as every bench scene of the peer kind). It is read from
 * our own scene file, so the peers render what we render.
 *
 * @param eye              the camera's position
 * @param at               the point it looks at
 * @param up               its up direction
 * @param verticalFov      vertical field of view, degrees
 * @param width            image width, pixels
 * @param height           image height, pixels
 * @param light            the point light's position
 * @param radiantIntensity the light's radiant intensity, W/sr (with the 1/pi of a Lambert BRDF)
 * @param meshes           the OBJ files, in the scene's order
 */
record PeerView(Vec3 eye, Vec3 at, Vec3 up, double verticalFov, int width, int height, Vec3 light, double radiantIntensity,
                List<Path> meshes) {
    /**
     * The view of {@code scene}, whose meshes are {@code meshes}. Our Whitted diffuse term is
     * kd * colour * cos, without the 1/pi of a Lambert BRDF, so the scene's intensity is the
     * radiant intensity divided by pi (scenes/bench/torus-1m.dat).
     *
     * @throws IOException if the scene is not of the kind the peers are given (one white
     *         inverse-square point light, a pinhole camera)
     */
    static PeerView of(SceneBuilder scene, List<Path> meshes) throws IOException {
        if (!(scene.camera() instanceof PinholeCamera cam)) throw new IOException("a peer view needs a pinhole camera");
        if (scene.lights().size() != 1) throw new IOException("a peer view needs exactly one light, found " + scene.lights().size());
        PointLight l = scene.lights().get(0);
        if (l.falloff() != PointLight.Falloff.INVERSE_SQUARE || l.color().r() != 1 || l.color().g() != 1 || l.color().b() != 1) {
            throw new IOException("a peer view needs a white light with inverse-square falloff");
        }
        return new PeerView(cam.eye(), cam.lookAt(), cam.up(), cam.fovDegrees(), scene.settings().width(), scene.settings().height(),
                l.position(), l.intensity() * Math.PI, List.copyOf(meshes));
    }

    /** {@return the horizontal field of view in degrees, for the renderers that take that one} */
    double horizontalFov() {
        return Math.toDegrees(2 * Math.atan(Math.tan(Math.toRadians(verticalFov / 2)) * width / height));
    }
}
